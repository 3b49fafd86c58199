// The paper slope at refine = 2 (element size about 2/2 m) for the error-against-run-time
// study (src/study.rs). Same geometry and groups as verification/cases/slope/slope.geo.
refine = 2;
Include "../cases/slope/slope.geo";

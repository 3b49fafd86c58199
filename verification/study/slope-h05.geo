// The paper slope at refine = 4 (element size about 2/4 m) for the error-against-run-time
// study (src/study.rs). Same geometry and groups as verification/cases/slope/slope.geo.
refine = 4;
Include "../cases/slope/slope.geo";

// The paper slope at refine = 0.5 (element size about 2/0.5 m) for the error-against-run-time
// study (src/study.rs). Same geometry and groups as verification/cases/slope/slope.geo.
refine = 0.5;
Include "../cases/slope/slope.geo";

// The laterally confined column with 20 layers for the error-against-run-time study
// (src/study.rs). Same geometry and groups as verification/cases/column/column.geo.
layers = 20;
Include "../cases/column/column.geo";

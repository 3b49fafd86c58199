// The laterally confined column with 40 layers for the error-against-run-time study
// (src/study.rs). Same geometry and groups as verification/cases/column/column.geo.
layers = 40;
Include "../cases/column/column.geo";

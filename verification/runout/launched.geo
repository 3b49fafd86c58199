// A block launched along a level plane: 2 m long, 2 m high.
h = 2; w = 2; nz = 1; gap = 0; x_end = 12;
Include "block.geo";

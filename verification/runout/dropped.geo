// A block dropped onto a level plane from 1 m: 2 m long, 2 m high, no shared nodes.
h = 2; w = 2; nz = 1; gap = 1; x_end = 6;
Include "block.geo";

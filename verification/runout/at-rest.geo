// 3DEC's block at rest: 10 m long, 10 m high.
h = 10; w = 10; nz = 2; gap = 0; x_end = 16;
Include "block.geo";

// 3DEC's sliding block (Itasca, after Wyllie & Mah 2004): 10 m long, 5 m high.
h = 5; w = 10; nz = 1; gap = 0; x_end = 26;
Include "block.geo";

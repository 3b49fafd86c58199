// 3DEC's toppling block: 10 m long, 25 m high (w / h = 0.4 < tan 40 deg).
h = 25; w = 10; nz = 5; gap = 0; x_end = 44;
Include "block.geo";

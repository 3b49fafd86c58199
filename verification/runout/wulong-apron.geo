// The Wulong section (../cases/wulong/wulong.geo) with its toe platform (National Road 319
// and the building, z = 20 m, x = 0-30 m) continued 90 m further from the slope, to
// x = -90 m, as level ground (the same frame rock, fixed at its base): somewhere for the
// blocks of a runout to land and come to rest (verification/runout/wulong-*-runout.toml).
// Everything else, the jointed zone and its groups, is the paper case's mesh.
apron = 90;
Include "../cases/wulong/wulong.geo";

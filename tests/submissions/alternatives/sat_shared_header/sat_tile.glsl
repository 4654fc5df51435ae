// sat_tile.glsl: the tile size sat.comp and sat_lookup.glsl must agree on, in one header both
// include (a correct solution that shares a file; graded by tests/test_hostile_submission_includes.cpp).
#ifndef SAT_TILE_GLSL
#define SAT_TILE_GLSL
#define SAT_TILE 32
#endif

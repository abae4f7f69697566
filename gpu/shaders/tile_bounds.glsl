#version 430 core
// The tile bounds' reduction (gpu/src/document/tile_bounds_pass): one invocation per quarter of
// a tile, the min and max of the positions' xyz over the quarter's samples and the first sample
// past it in i and j (core::TileBounds::rectBox), written to the quarter's slot. A quarter is at
// most 17 × 17 samples: a loop of its own beats a shared-memory reduction, whose barriers a
// software rasterizer runs slowly.
layout(local_size_x = 64) in;

uniform sampler2D u_positions;
uniform ivec2 u_last; // W, H: the image's last sample index along i and j
uniform int u_count; // quarters

layout(std430, binding = 2) readonly buffer Quarters {
  ivec4 quarters[]; // x, y, width, height
};
layout(std430, binding = 3) writeonly buffer Boxes {
  vec4 boxes[]; // min, max per quarter
};

void main() {
  int k = int(gl_GlobalInvocationID.x);
  if (k >= u_count) return;
  ivec4 r = quarters[k];
  int lastI = min(r.x + r.z, u_last.x), lastJ = min(r.y + r.w, u_last.y);
  vec3 lo = texelFetch(u_positions, r.xy, 0).xyz, hi = lo;
  for (int j = r.y; j <= lastJ; ++j)
    for (int i = r.x; i <= lastI; ++i) {
      vec3 p = texelFetch(u_positions, ivec2(i, j), 0).xyz;
      lo = min(lo, p);
      hi = max(hi, p);
    }
  boxes[2 * k] = vec4(lo, 0.0);
  boxes[2 * k + 1] = vec4(hi, 0.0);
}

#version 430 core
// The area normal's reduction (gpu/src/document/area_normal_pass): one invocation per quarter
// of a tile near the dab, the sum of the area vectors (cross products) of the quarter's cells'
// triangles whose centroid lies within the radius of the centre, and their count. Only these
// sums (16 bytes a quarter) are read back, not the texels under the dab.
layout(local_size_x = 64) in;

uniform sampler2D u_positions;
uniform ivec2 u_cells;  // W, H: the image's cells along i and j (N, N on the ball)
uniform int u_ball;     // 1: the octahedral split (anti-diagonal where i and j share a half)
uniform vec3 u_centre;
uniform float u_radius2;
uniform int u_count;    // quarters

layout(std430, binding = 2) readonly buffer Quarters {
  ivec4 quarters[]; // x, y, width, height (samples)
};
layout(std430, binding = 3) writeonly buffer Sums {
  vec4 sums[]; // xyz: the area vectors' sum, w: the triangles counted
};

precise vec3 sum;
int triangles;

void add(vec3 a, vec3 b, vec3 c) {
  precise vec3 d = (a + b + c) * (1.0 / 3.0) - u_centre;
  if (dot(d, d) > u_radius2) return;
  sum += cross(b - a, c - a);
  ++triangles;
}

void main() {
  int k = int(gl_GlobalInvocationID.x);
  if (k >= u_count) return;
  ivec4 r = quarters[k];
  int iEnd = min(r.x + r.z, u_cells.x), jEnd = min(r.y + r.w, u_cells.y);
  int half_ = u_cells.x / 2;
  sum = vec3(0.0);
  triangles = 0;
  for (int j = r.y; j < jEnd; ++j)
    for (int i = r.x; i < iEnd; ++i) {
      vec3 a = texelFetch(u_positions, ivec2(i, j), 0).xyz;
      vec3 b = texelFetch(u_positions, ivec2(i + 1, j), 0).xyz;
      vec3 c = texelFetch(u_positions, ivec2(i + 1, j + 1), 0).xyz;
      vec3 d = texelFetch(u_positions, ivec2(i, j + 1), 0).xyz;
      // core::cellTriangles: the torus and plane split every cell along its anti-diagonal.
      if (u_ball == 0 || (i < half_) == (j < half_)) {
        add(a, b, d);
        add(b, c, d);
      } else {
        add(a, b, c);
        add(a, c, d);
      }
    }
  sums[k] = vec4(sum, float(triangles));
}

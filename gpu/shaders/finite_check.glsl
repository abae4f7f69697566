#version 430 core
// The stroke's finite check (gpu/src/document/finite_check_pass): one invocation per row of a
// rectangle; a texel with a non-finite channel, or (u_bounded) an xyz beyond u_maxCoordinate,
// sets the flag. The bits are tested, not isnan/isinf, which a compiler may fold away.
layout(local_size_x = 64) in;

uniform sampler2D u_layer;
uniform int u_channels;
uniform bool u_bounded;
uniform float u_maxCoordinate;
uniform int u_rows; // rows in all

layout(std430, binding = 2) readonly buffer Rows {
  ivec4 rows[]; // x, y, width, 1: one per invocation
};
layout(std430, binding = 3) buffer Flag {
  uint flag;
};

void main() {
  int k = int(gl_GlobalInvocationID.x);
  if (k >= u_rows) return;
  ivec4 r = rows[k];
  bool bad = false;
  for (int i = r.x; i < r.x + r.z; ++i) {
    vec4 t = texelFetch(u_layer, ivec2(i, r.y), 0);
    for (int c = 0; c < u_channels; ++c) {
      bad = bad || (floatBitsToUint(t[c]) & 0x7f800000u) == 0x7f800000u;
      bad = bad || (u_bounded && c < 3 && abs(t[c]) > u_maxCoordinate);
    }
  }
  if (bad) atomicOr(flag, 1u);
}

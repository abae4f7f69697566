#version 430 core
// A level-of-detail mesh (core::generateLod) drawn as a triangle list: each corner carries its
// position and its image coordinates, so model_fragment.glsl shades it from the full-resolution
// normal map as it shades the displayed level.
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec2 a_imageUv; // (i / N, j / N) of the sample it came from
uniform mat4 u_objectToClip;
uniform int u_imageSide; // N + 1

out vec3 v_position;
out vec2 v_uv;
out vec3 v_corner; // one-hot per corner: the wireframe's barycentric coordinates

void main() {
  v_position = a_position;
  // Sample i's texel centre is (i + 0.5) / (N + 1).
  float n = float(u_imageSide - 1);
  v_uv = (a_imageUv * n + 0.5) / float(u_imageSide);
  v_corner = vec3(equal(ivec3(gl_VertexID % 3), ivec3(0, 1, 2)));
  gl_Position = u_objectToClip * vec4(a_position, 1.0);
}

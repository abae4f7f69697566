#version 430 core
// The displayed level: vertex k is sample (i, j) * u_step of the image, i = k mod (M+1).
uniform sampler2D u_positions;
uniform mat4 u_objectToClip;
uniform int u_step;
uniform int u_side; // M + 1
uniform int u_imageSide; // N + 1 (W + 1)
uniform ivec2 u_imageSize; // W + 1, H + 1: the image's texels along i and j

out vec3 v_position;
out vec2 v_uv;
out vec2 v_cell; // the vertex in displayed cells (the wireframe's grid)

void main() {
  // Float division: exact for these ids (< 2^24) and far cheaper than an integer division
  // lane by lane on a software rasterizer.
  int row = int((float(gl_VertexID) + 0.5) / float(u_side));
  ivec2 cell = ivec2(gl_VertexID - row * u_side, row) * u_step;
  v_position = texelFetch(u_positions, cell, 0).xyz;
  v_uv = (vec2(cell) + 0.5) / vec2(u_imageSize);
  v_cell = vec2(gl_VertexID - row * u_side, row);
  gl_Position = u_objectToClip * vec4(v_position, 1.0);
}

// The seaming pass: each border sample becomes the average of the samples identified with it
// (core/src/seaming.cpp), so identified samples are equal again after a dab.
uniform sampler2D u_source;
uniform ivec2 u_cells;  // W, H: the image has (W+1) x (H+1) samples (N, N on the ball)
uniform int u_topology; // 0 octahedral, 1 torus (column W and row H are column and row 0), 2 plane
out vec4 o_value;

void main() {
  int n = u_cells.x, h = u_cells.y;
  ivec2 t = ivec2(gl_FragCoord.xy);
  bool sideI = t.x == 0 || t.x == n;
  bool sideJ = t.y == 0 || t.y == h;
  vec4 value = texelFetch(u_source, t, 0);
  if (u_topology == 2) {
    // a plane has no seams
  } else if (sideI && sideJ) {
    // Summed in pairs so four equal corners average to exactly their value.
    value = 0.25 * ((texelFetch(u_source, ivec2(0, 0), 0) + texelFetch(u_source, ivec2(n, 0), 0)) +
                    (texelFetch(u_source, ivec2(0, h), 0) + texelFetch(u_source, ivec2(n, h), 0)));
  } else if (u_topology == 1 && sideI) {
    value = 0.5 * (value + texelFetch(u_source, ivec2(n - t.x, t.y), 0));
  } else if (u_topology == 1 && sideJ) {
    value = 0.5 * (value + texelFetch(u_source, ivec2(t.x, h - t.y), 0));
  } else if (sideI) {
    value = 0.5 * (value + texelFetch(u_source, ivec2(t.x, n - t.y), 0));
  } else if (sideJ) {
    value = 0.5 * (value + texelFetch(u_source, ivec2(n - t.x, t.y), 0));
  }
  o_value = value;
}

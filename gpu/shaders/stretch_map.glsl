// Stretch-map pass: per texel, the largest singular value of the Jacobian from the image (one
// sample step) to the surface, the maximum over the triangles around the texel: what
// core::measureStretch (core/src/measure/stretch.cpp) gives before dividing by the mean
// spacing, so the preview can follow every dab. The host prepends the version, the layer
// defines and the prelude (wrapTexel, fetchPositions).
out vec4 o_stretch;

// core's cellSplit() on the tiled plane: quadrants of N/2 cells form a checkerboard, and those
// of the square's lower-left and upper-right are split along the anti-diagonal.
bool antiDiagonal(ivec2 cell) {
  if (u_topology != 0) return true; // a torus or plane splits every cell so
  int halfSize = u_size / 2;
  ivec2 q = ivec2(cell.x >= 0 ? cell.x / halfSize : -1 - (-1 - cell.x) / halfSize,
                  cell.y >= 0 ? cell.y / halfSize : -1 - (-1 - cell.y) / halfSize);
  return ((q.x ^ q.y) & 1) == 0;
}

// Largest singular value of the 3×2 matrix [du dv]: √ of the larger eigenvalue of its Gram
// matrix. Non-finite figures count as 0, as the CPU skips such triangles.
float sigmaMax(vec3 du, vec3 dv) {
  float a = dot(du, du), b = dot(du, dv), c = dot(dv, dv);
  float h = 0.5 * (a - c);
  float s = sqrt(0.5 * (a + c) + sqrt(h * h + b * b));
  return s < 3.0e38 ? s : 0.0;
}

void main() {
  ivec2 t = ivec2(gl_FragCoord.xy);
  vec3 p[9]; // the 3×3 block around t through wrap(): p[(dj + 1) * 3 + di + 1]
  for (int dj = -1; dj <= 1; ++dj)
    for (int di = -1; di <= 1; ++di)
      p[(dj + 1) * 3 + di + 1] = fetchPositions(t + ivec2(di, dj)).xyz;
  float s = 0.0;
  // The four cells with corner t; t is their corner c, d, b and a in turn. With a = (i, j),
  // b = (i+1, j), c = (i+1, j+1), d = (i, j+1): anti-diagonal cells hold {a, b, d}, {b, c, d};
  // main-diagonal ones {a, b, c}, {a, c, d} (core's cellTriangles()).
  for (int cj = -1; cj <= 0; ++cj)
    for (int ci = -1; ci <= 0; ++ci) {
      int k = (cj + 1) * 3 + ci + 1;
      vec3 a = p[k], b = p[k + 1], c = p[k + 4], d = p[k + 3];
      bool anti = antiDiagonal(t + ivec2(ci, cj));
      bool atA = ci == 0 && cj == 0, atB = ci == -1 && cj == 0;
      bool atC = ci == -1 && cj == -1, atD = ci == 0 && cj == -1;
      if (anti) {
        if (atA || atB || atD) s = max(s, sigmaMax(b - a, d - a));
        if (atB || atC || atD) s = max(s, sigmaMax(c - d, c - b));
      } else {
        if (atA || atB || atC) s = max(s, sigmaMax(b - a, c - b));
        if (atA || atC || atD) s = max(s, sigmaMax(c - d, d - a));
      }
    }
  o_stretch = vec4(s, 0.0, 0.0, 1.0);
}

// Saliency, pass 1: each sample's unit normal as core::vertexNormal computes it (the
// area-weighted sum of its incident triangles' normals through wrap()), so the GPU saliency
// follows the CPU reference. The host prepends the version and the prelude (wrapTexel,
// fetchPositions, u_size).
out vec4 o_normal;

int floorDivide(int a, int b) { return a >= 0 ? a / b : -((b - 1 - a) / b); }

// core::cellSplit: cells split along the anti-diagonal where both halfSide-side indices have the
// same parity.
bool antiDiagonal(ivec2 cell) {
  if (u_topology != 0) return true; // a torus and a plane split every cell so (cellTriangles)
  int halfSide = u_size / 2;
  return ((floorDivide(cell.x, halfSide) & 1) != 0) == ((floorDivide(cell.y, halfSide) & 1) != 0);
}

vec3 position(ivec2 s) { return fetchPositions(s).xyz; }

// Adds the cross product at s of each triangle of the cell with lower-left corner c that has s as
// a corner (core::incidentTriangles' order).
vec3 cellContribution(ivec2 c, ivec2 s, vec3 p) {
  ivec2 a = c, b = c + ivec2(1, 0), cc = c + ivec2(1, 1), d = c + ivec2(0, 1);
  ivec2 tri[6];
  if (antiDiagonal(c)) {
    tri[0] = a; tri[1] = b; tri[2] = d; tri[3] = b; tri[4] = cc; tri[5] = d;
  } else {
    tri[0] = a; tri[1] = b; tri[2] = cc; tri[3] = a; tri[4] = cc; tri[5] = d;
  }
  vec3 sum = vec3(0.0);
  for (int t = 0; t < 2; ++t)
    for (int k = 0; k < 3; ++k)
      if (tri[3 * t + k] == s) {
        ivec2 q1 = tri[3 * t + (k + 1) % 3], q2 = tri[3 * t + (k + 2) % 3];
        sum += cross(position(q1) - p, position(q2) - p);
      }
  return sum;
}

void main() {
  ivec2 s = ivec2(gl_FragCoord.xy);
  int n = u_size, halfSide = u_size / 2;
  // The ball's side midpoints are halfSide-turn centres: only the cells on one side of the
  // fold count. A torus's neighbours wrap; a plane's cells past its boundary are degenerate
  // (clamped corners) and add nothing.
  bool ball = u_topology == 0;
  bool verticalMidpoint = ball && (s.x == 0 || s.x == n) && s.y == halfSide;
  bool horizontalMidpoint = ball && s.x == halfSide && (s.y == 0 || s.y == n);
  int diBegin = verticalMidpoint ? 0 : -1;
  int djBegin = horizontalMidpoint ? 0 : -1;
  vec3 p = position(s);
  vec3 sum = vec3(0.0);
  for (int dj = djBegin; dj <= 0; ++dj)
    for (int di = diBegin; di <= 0; ++di)
      sum += cellContribution(s + ivec2(di, dj), s, p);
  float len = length(sum);
  o_normal = vec4(len > 0.0 ? sum / len : vec3(0.0), 0.0);
}

// Relax: each sample steps in the image towards its neighbours weighted by the length of the
// edge to them, raised to u_exponent (|X_k - X_c|^α, X the surface position), so samples move
// towards stretched areas and the surface's edges become more equal. A uniform average (every
// neighbour alike) would pull samples off a thin limb instead. The engine resamples every layer
// where the samples land, so the surface and its paint stay put.
vec2 brushOffset(BrushInput b) {
  vec3 centre = b.position;
  vec2 sum = vec2(0.0);
  float total = 0.0;
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx) {
      if (dx == 0 && dy == 0) continue;
      float w = pow(length(fetchPositions(b.texel + ivec2(dx, dy)).xyz - centre), u_exponent);
      sum += w * vec2(dx, dy);
      total += w;
    }
  // The gain of the step against an edge's change grows with the exponent: divided by it, the
  // iteration does not overshoot.
  return total > 0.0 ? (clamp(b.weight, 0.0, 1.0) / u_exponent) * (sum / total) : vec2(0.0);
}

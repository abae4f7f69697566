// Average of the eight neighbours read through wrap(), so smoothing does not stop at a seam.
vec4 brush(vec4 value, BrushInput b) {
  vec3 sum = vec3(0.0);
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx)
      if (dx != 0 || dy != 0) sum += fetchPositions(b.texel + ivec2(dx, dy)).xyz;
  return vec4(mix(value.xyz, sum / 8.0, clamp(b.weight, 0.0, 1.0)), value.w);
}

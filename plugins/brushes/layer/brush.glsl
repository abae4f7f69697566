// Each sample's height over its stroke-start position, along the stroke-start surface's normal
// there, becomes the larger of what it is and weight times the layer's height: the dabs of a
// stroke converge on one layer instead of piling up (a "target" stroke: each dab applies the
// whole strength).
vec4 brush(vec4 value, BrushInput b) {
  vec3 start = strokeStartAt(b.texel).xyz;
  vec3 n = strokeStartNormalAt(b.texel);
  float h = dot(value.xyz - start, n);
  float target = b.weight * u_height * u_radius;
  float wanted = u_height >= 0.0 ? max(h, target) : min(h, target);
  return vec4(value.xyz + n * (wanted - h), value.w);
}

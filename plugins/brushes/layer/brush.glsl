// Each sample's height over its stroke-start position becomes the larger of what it is and
// weight times the layer's height: the dabs of a stroke converge on one layer instead of piling
// up (a "target" stroke: each dab applies the whole strength). A sample rises along the centre
// normal of the first dab that lifts it and keeps that direction for the rest of the stroke: one
// read of the stroke-start positions a texel (a normal of the stroke-start surface would take
// four more, twice the cost of a push dab).
vec4 brush(vec4 value, BrushInput b) {
  // b.texel lies in the image: no wrap needed (strokeStartAt's costs a software rasterizer).
  vec3 up = value.xyz - texelFetch(u_strokeStart, b.texel, 0).xyz;
  float h = length(up);
  float target = b.weight * u_height * u_radius; // negative: a lowered layer
  vec3 direction = h > 1e-6 * u_radius ? up / h : u_centreNormal * sign(target);
  return vec4(value.xyz + direction * (max(h, abs(target)) - h), value.w);
}

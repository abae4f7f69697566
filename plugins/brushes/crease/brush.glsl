// Pinch across the stroke (the along-stroke part of the offset to the centre removed, so the
// sides close in on the stroke's line; radially before the stroke moves) plus a push inward along
// the centre normal by weight times the radius, as a pull of push.
vec4 brush(vec4 value, BrushInput b) {
  vec3 n = u_centreNormal;
  vec3 toCentre = u_centre - value.xyz;
  toCentre -= n * dot(toCentre, n);
  vec3 along = u_strokeDirection - n * dot(u_strokeDirection, n);
  if (dot(along, along) > 1e-12) {
    along = normalize(along);
    toCentre -= along * dot(toCentre, along);
  }
  float w = clamp(b.weight, -1.0, 1.0);
  return vec4(value.xyz + toCentre * (abs(w) * u_pinch) - n * (w * u_radius), value.w);
}

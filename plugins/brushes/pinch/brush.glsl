// Each sample moves towards the centre by weight times its offset from it within the tangent
// plane (the centre normal's component removed): distances between samples shrink, heights stay.
// The radial map r -> r (1 - w f(r)) keeps a positive slope for |w| <= 1 with smooth falloff
// (f + r f' lies in [-0.8, 1]), so the region never folds.
vec4 brush(vec4 value, BrushInput b) {
  vec3 toCentre = u_centre - value.xyz;
  toCentre -= u_centreNormal * dot(toCentre, u_centreNormal);
  return vec4(value.xyz + toCentre * clamp(b.weight, -1.0, 1.0), value.w);
}

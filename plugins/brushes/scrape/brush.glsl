// The plane lies u_depth radii below the centre, across the centre normal. A sample above it
// moves down towards it by the weight (full within the inner 40 % of the radius, then falling to
// the rim), never past it; a sample below it stays.
vec4 brush(vec4 value, BrushInput b) {
  float above = dot(value.xyz - u_centre, u_centreNormal) + u_depth * u_radius;
  if (above <= 0.0) return value;
  return vec4(value.xyz - u_centreNormal * (above * clamp(b.weight, 0.0, 1.0)), value.w);
}

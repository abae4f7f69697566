vec4 brush(vec4 value, BrushInput b) {
  float height = dot(value.xyz - u_centre, u_centreNormal);
  return vec4(value.xyz - u_centreNormal * height * clamp(b.weight, 0.0, 1.0), value.w);
}

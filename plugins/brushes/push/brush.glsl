// Every sample moves the same way (the centre's normal) by strength × falloff × radius. With
// linear falloff that displacement changes by at most `strength` per unit of distance, so for
// strengths up to 1 no two points of space land on the same spot and the surface cannot cross
// itself. The area mode is "volume" for the same reason: a normal cut-off would tear the field.
vec4 brush(vec4 value, BrushInput b) {
  return vec4(value.xyz + u_centreNormal * (b.weight * u_radius), value.w);
}

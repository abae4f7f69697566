// Every sample moves the same way (the centre's normal), scaled by the falloff: with linear
// falloff the moved surface stays a graph over the brush plane, so it cannot fold over itself.
vec4 brush(vec4 value, BrushInput b) {
  return vec4(value.xyz + u_centreNormal * (b.weight * u_radius), value.w);
}

vec4 brush(vec4 value, BrushInput b) {
  return vec4(value.xyz + b.normal * (b.weight * u_radius), value.w);
}

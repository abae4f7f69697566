vec4 brush(vec4 value, BrushInput b) {
  return mix(value, u_color, clamp(b.weight, 0.0, 1.0));
}

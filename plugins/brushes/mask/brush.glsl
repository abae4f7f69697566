vec4 brush(vec4 value, BrushInput b) {
  float target = u_erase > 0.5 ? 1.0 : 0.0;
  return vec4(mix(value.r, target, clamp(b.weight, 0.0, 1.0)), value.gba);
}

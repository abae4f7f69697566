vec4 brush(vec4 value, BrushInput b) {
  float w = clamp(b.weight, 0.0, 1.0);
  if (u_mode == 1) // erase: back to the unpainted mask; full weight restores it exactly
    return vec4(w >= 1.0 ? u_layerFill.r : mix(value.r, u_layerFill.r, w), value.gba);
  return vec4(mix(value.r, 0.0, w), value.gba);
}

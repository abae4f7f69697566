// An anchored stroke: one dab where the stroke began, run again each time the drag changes.
// Every sample is its stroke-start position moved by the drag times its weight, which the engine
// measures on the stroke-start surface (BRUSH_ANCHORED), so a dab never compounds the last one.
// With linear falloff the displacement changes by at most |drag| / radius per unit of distance:
// up to a drag of one radius no two points of space land on the same spot.
vec4 brush(vec4 value, BrushInput b) {
  return vec4(strokeStartAt(b.texel).xyz + u_drag * b.weight, value.w);
}

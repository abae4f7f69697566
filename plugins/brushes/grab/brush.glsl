// An anchored stroke: one dab where the stroke began, run again each time the drag changes.
// b.position is the sample's stroke-start position and b.weight is measured there
// (BRUSH_ANCHORED), so every run moves the stroke-start surface by the drag times the weight and
// never compounds the last one. With linear falloff the displacement changes by at most
// |drag| / radius per unit of distance: below a drag of one radius no two points of space land on
// the same spot.
vec4 brush(vec4 value, BrushInput b) {
  return vec4(b.position + u_drag * b.weight, value.w);
}

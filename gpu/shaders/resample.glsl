// The resampling pass after a reparameterize brush's steps: every layer at texel + offset
// (u_offsets), read from the layers as they were before the dab and interpolated on the grid's
// own triangles (prelude's planeValue), so a position lies on the old piecewise-linear surface
// and the paint stays on the same surface points. A texel with no offset keeps its bits.
// The host prepends the prelude with BRUSH_REPARAMETERIZE defined and attaches only the layers
// it resamples.
layout(location = 0) out vec4 o_positions;
layout(location = 1) out vec4 o_diffuse;
layout(location = 2) out vec4 o_feature;
layout(location = 3) out vec4 o_mask;

void main() {
  ivec2 t = ivec2(gl_FragCoord.xy);
  vec2 offset = texelFetch(u_offsets, t, 0).xy;
  if (offset == vec2(0.0)) {
    o_positions = texelFetch(u_positions, t, 0);
    o_diffuse = texelFetch(u_diffuseLayer, t, 0);
    o_feature = texelFetch(u_featureLayer, t, 0);
    o_mask = texelFetch(u_mask, t, 0);
    return;
  }
  ivec2 c0, c1, c2;
  vec3 w;
  cellTriangleAt(vec2(t) + offset, c0, c1, c2, w); // planeValue's triangle, found once
  ivec2 a = wrapTexel(c0), b = wrapTexel(c1), c = wrapTexel(c2);
#define RESAMPLED(s) (w.x * texelFetch(s, a, 0) + w.y * texelFetch(s, b, 0) + w.z * texelFetch(s, c, 0))
  o_positions = RESAMPLED(u_positions);
  o_diffuse = RESAMPLED(u_diffuseLayer);
  o_feature = RESAMPLED(u_featureLayer);
  o_mask = RESAMPLED(u_mask);
}

// Saliency, pass 3: one direction of a separable Gaussian (sigma u_sigma, taps out to
// u_taps = max(1, ceil(2 sigma))) over the octahedral tiling of the plane. The tiling's symmetries are
// translations and half-turns, which map rows to rows and columns to columns, so a horizontal
// then a vertical pass through wrap() is the 2D Gaussian over the tiled surface. The host
// prepends the version and the prelude (wrapTexel, u_size).
uniform sampler2D u_source;
uniform ivec2 u_direction;
uniform float u_sigma;
uniform int u_taps;
out vec4 o_value;

void main() {
  ivec2 s = ivec2(gl_FragCoord.xy);
  float k = -0.5 / (u_sigma * u_sigma);
  float sum = 0.0, weights = 0.0;
  for (int d = -u_taps; d <= u_taps; ++d) {
    float w = exp(k * float(d * d));
    sum += w * texelFetch(u_source, wrapTexel(s + d * u_direction), 0).r;
    weights += w;
  }
  o_value = vec4(sum / weights, 0.0, 0.0, 0.0);
}

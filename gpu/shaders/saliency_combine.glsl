// Saliency, pass 4: adds one centre-surround term |G(c, s) - G(c, 2s)| to the running sum.
uniform sampler2D u_fine;
uniform sampler2D u_coarse;
uniform sampler2D u_sum;
out vec4 o_value;

void main() {
  ivec2 s = ivec2(gl_FragCoord.xy);
  float term = abs(texelFetch(u_fine, s, 0).r - texelFetch(u_coarse, s, 0).r);
  o_value = vec4(texelFetch(u_sum, s, 0).r + term, 0.0, 0.0, 0.0);
}

#version 330 core
// Thick lines, stage 3: anti-aliased edge from the distance to the centre line.
in vec4 gColor;
noperspective in float gAcross;
uniform float uWidth;
out vec4 fragColor;
void main() {
  float coverage = clamp(0.5 * uWidth + 0.5 - abs(gAcross), 0.0, 1.0);
  if (coverage <= 0.0) discard;
  fragColor = vec4(gColor.rgb, gColor.a * coverage);
}

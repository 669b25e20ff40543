// Thick lines: anti-aliased edge from the distance to the centre line.
in vec4 vColor;
in float vAcrossW;
in float vW;
uniform float uWidth;
out vec4 fragColor;
void main() {
  float across = vAcrossW / vW;
  float coverage = clamp(0.5 * uWidth + 0.5 - abs(across), 0.0, 1.0);
  if (coverage <= 0.0) discard;
  fragColor = vec4(vColor.rgb, vColor.a * coverage);
}

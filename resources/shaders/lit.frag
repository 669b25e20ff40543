// Lit surface: Blinn-Phong + hemisphere ambient + PCF shadows (lighting.glsl), sRGB output.
#include "lighting.glsl"

in vec3 vWorldPos;
in vec3 vNormal;
in vec4 vColor;
out vec4 fragColor;

void main() {
  vec3 color = shade(vColor.rgb, vWorldPos, normalize(vNormal), 0.35);
  fragColor = vec4(toSrgb(color), vColor.a);
}

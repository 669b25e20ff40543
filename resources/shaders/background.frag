// Soft vertical gradient, light enough for a projector.
in float vHeight;
uniform vec3 uTop;     // sRGB
uniform vec3 uBottom;  // sRGB
out vec4 fragColor;
void main() { fragColor = vec4(mix(uBottom, uTop, smoothstep(0.0, 1.0, vHeight)), 1.0); }

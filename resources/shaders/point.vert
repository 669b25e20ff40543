#version 330 core
// Screen-sized dots, stage 1.
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec4 aColor;
layout(location = 2) in float aSize;  // diameter, pixels
uniform mat4 uViewProj;
out vec4 vColor;
out float vSize;
void main() {
  vColor = aColor;
  vSize = aSize;
  gl_Position = uViewProj * vec4(aPosition, 1.0);
}

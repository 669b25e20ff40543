// Shadow depth pass for instanced primitives (same attribute layout as lit.vert).
layout(location = 0) in vec3 aPosition;
layout(location = 2) in mat4 aModel;

uniform mat4 uLightViewProj;

void main() { gl_Position = uLightViewProj * aModel * vec4(aPosition, 1.0); }

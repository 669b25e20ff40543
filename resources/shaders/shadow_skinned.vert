// Shadow depth pass for skinned meshes (same skinning as skinned.vert).
layout(location = 0) in vec3 aPosition;
layout(location = 2) in ivec4 aBoneIds;
layout(location = 3) in vec4 aBoneWeights;

layout(std140) uniform Bones {
  mat4 uBones[128];
};
uniform mat4 uModel;
uniform mat4 uLightViewProj;

void main() {
  mat4 skin = aBoneWeights.x * uBones[aBoneIds.x] + aBoneWeights.y * uBones[aBoneIds.y] +
              aBoneWeights.z * uBones[aBoneIds.z] + aBoneWeights.w * uBones[aBoneIds.w];
  gl_Position = uLightViewProj * uModel * skin * vec4(aPosition, 1.0);
}

#version 330 core
// A mesh, once per instance: model = uFrame · aInstance · skin, where skin is the identity for a
// rigid mesh and, for a skinned one (uSkinned), linear blend skinning as model/skinning.h writes it:
// skin = Σ_k w_k · J_{j_k} + (1 − Σ_k w_k) · I, with the joint matrices J from the uniform block. Instances blend from uColor (the first) to
// uColorEnd (the last), so a stroboscopic trail shows which way the motion runs; the instance
// uHighlightInstance (or none, −1) takes uHighlightColor.
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in mat4 aInstance;
layout(location = 6) in uvec4 aJoints;
layout(location = 7) in vec4 aWeights;

// model::kMaxSkinJoints matrices: 16 KiB, the uniform block size every OpenGL 3.3 driver allows.
layout(std140) uniform JointMatrices {
    mat4 uJoints[256];
};
uniform bool uSkinned;

uniform mat4 uViewProjection;
uniform mat4 uFrame;
uniform vec4 uColor;
uniform vec4 uColorEnd;
uniform int uInstanceCount;
uniform int uHighlightInstance;
uniform vec4 uHighlightColor;

out vec3 vWorldPosition;
out vec3 vNormal;
out vec4 vColor;

void main()
{
    mat4 skin = mat4(1.0);
    if (uSkinned) {
        skin = aWeights.x * uJoints[aJoints.x] + aWeights.y * uJoints[aJoints.y] + aWeights.z * uJoints[aJoints.z]
               + aWeights.w * uJoints[aJoints.w] + (1.0 - dot(aWeights, vec4(1.0))) * mat4(1.0);
    }
    mat4 model = uFrame * aInstance * skin;
    vec4 world = model * vec4(aPosition, 1.0);
    vWorldPosition = world.xyz;
    // Rigid motions, uniform scales and their blends: the normal turns with the model, and is renormalised.
    vNormal = mat3(model) * aNormal;
    float along = uInstanceCount > 1 ? float(gl_InstanceID) / float(uInstanceCount - 1) : 0.0;
    vColor = gl_InstanceID == uHighlightInstance ? uHighlightColor : mix(uColor, uColorEnd, along);
    gl_Position = uViewProjection * world;
}

#version 330 core
// A mesh, once per instance: model = uFrame · aInstance. Instances blend from uColor (the first) to
// uColorEnd (the last), so a stroboscopic trail shows which way the motion runs; the instance
// uHighlightInstance (or none, −1) takes uHighlightColor.
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in mat4 aInstance;

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
    mat4 model = uFrame * aInstance;
    vec4 world = model * vec4(aPosition, 1.0);
    vWorldPosition = world.xyz;
    // Rigid motions and uniform scales only: the normal turns with the model, and is renormalised.
    vNormal = mat3(model) * aNormal;
    float along = uInstanceCount > 1 ? float(gl_InstanceID) / float(uInstanceCount - 1) : 0.0;
    vColor = gl_InstanceID == uHighlightInstance ? uHighlightColor : mix(uColor, uColorEnd, along);
    gl_Position = uViewProjection * world;
}

#version 330 core
// A headlight: diffuse by |n·l| towards the eye, both sides lit, since imported meshes do not all
// wind their triangles the same way; plus an ambient part so that faces edge-on stay visible.
in vec3 vWorldPosition;
in vec3 vNormal;
in vec4 vColor;

uniform vec3 uEye;

out vec4 fragColor;

void main()
{
    vec3 normal = normalize(vNormal);
    vec3 towardsEye = normalize(uEye - vWorldPosition);
    float diffuse = abs(dot(normal, towardsEye));
    fragColor = vec4(vColor.rgb * (0.35 + 0.65 * diffuse), vColor.a);
}

#version 330 core
// Lines and points given in world coordinates, each vertex with its colour.
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec4 aColor;

uniform mat4 uViewProjection;
uniform float uPointSize;

out vec4 vColor;

void main()
{
    vColor = aColor;
    gl_PointSize = uPointSize;
    gl_Position = uViewProjection * vec4(aPosition, 1.0);
}

#version 330 core
// SPDX-License-Identifier: MIT
// Faint glass: nearly clear where the wall faces the camera, denser at grazing angles (a
// cheap Fresnel look), so the silhouette of the vessel reads without hiding the sand.
in float facing;
uniform vec3 glassColor;
uniform float baseAlpha;
uniform float rimAlpha;
out vec4 fragColor;

void main() {
    float rim = pow(1.0 - facing, 2.0);
    fragColor = vec4(glassColor, baseAlpha + rimAlpha * rim);
}

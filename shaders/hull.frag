#version 330 core
// SPDX-License-Identifier: MIT
// Faint glass: nearly clear where the wall faces the camera, denser at grazing angles (a
// cheap Fresnel look), so the silhouette of the vessel reads without hiding the sand. With the
// studio's environment (look.glsl) the wall mirrors the sky and ground, more so at grazing angles.
in float facing;
in vec3 worldPosition;
in vec3 worldNormal;
uniform vec3 glassColor;
uniform float baseAlpha;
uniform float rimAlpha;
uniform vec3 cameraPosition;

#include "look.glsl"

out vec4 fragColor;

void main() {
    float rim = pow(1.0 - facing, 2.0);
    if (studio && environment && dot(worldNormal, worldNormal) > 0.5) {
        vec3 view = normalize(cameraPosition - worldPosition);
        vec3 n = normalize(worldNormal);
        if (dot(n, view) < 0.0) n = -n;
        float fresnel = 0.04 + 0.96 * pow(1.0 - facing, 5.0);
        vec3 color = toDisplay(mix(toLinear(glassColor), environmentLight(reflect(-view, n)), fresnel + 0.3 * rim));
        fragColor = vec4(color, baseAlpha + rimAlpha * rim + 0.25 * fresnel);
        return;
    }
    fragColor = vec4(glassColor, baseAlpha + rimAlpha * rim);
}

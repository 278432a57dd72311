#version 330 core
// SPDX-License-Identifier: MIT
// Frame and static parts: opaque, two-sided (a model with inconsistent winding still shades).
// Under the studio lights (look.glsl) lit by the key, its shadow, the fill and the sky; under
// the thesis's by the light near the camera and a sky from above. Glass: nearly clear where it
// faces the eye, with a Schlick Fresnel rim at grazing angles and a highlight, so both walls read
// without hiding the sand behind them; with the environment on, the rim reflects the sky.
in vec3 worldPosition;
in vec3 worldNormal;
in vec3 partColor;

uniform vec3 cameraPosition;
uniform vec3 lightPosition;
uniform int glass;            // 1: glass, 0: opaque
uniform int blackBackground;  // glass: lighter tint on black, deeper on white

#include "look.glsl"

out vec4 fragColor;

void main() {
    vec3 view = normalize(cameraPosition - worldPosition);
    vec3 n = normalize(worldNormal);
    if (dot(n, view) < 0.0) n = -n; // the side that faces the eye
    if (studio && glass == 0) {
        vec3 halfway = normalize(keyDirection + view);
        float lit = keyLightReaching(worldPosition, n);
        float specular = pow(max(dot(n, halfway), 0.0), 24.0) * 0.08 * lit * float(dot(n, keyDirection) > 0.0);
        // The part colours were picked under the thesis's light, which lit sRGB values; lit in
        // linear values they come out more saturated, so a quarter of the saturation is taken back.
        vec3 albedo = toLinear(mix(vec3(dot(partColor, vec3(0.299, 0.587, 0.114))), partColor, 0.75));
        fragColor = vec4(toDisplay(studioLight(albedo, n, 1.0, lit) + keyColor * specular), 1.0);
        return;
    }
    vec3 toLight = normalize(lightPosition - worldPosition);
    vec3 halfway = normalize(toLight + view);
    float diffuse = max(dot(n, toLight), 0.0);
    if (glass == 0) {
        // The light near the eye plus a sky from above, so faces seen at a grazing angle from
        // the camera (a plate's top) are not left in the dark.
        float sky = 0.5 + 0.5 * n.y;
        float specular = pow(max(dot(n, halfway), 0.0), 24.0) * 0.12;
        fragColor = vec4(partColor * (0.25 + 0.35 * sky + 0.55 * diffuse) + vec3(specular), 1.0);
        return;
    }
    float facing = clamp(dot(n, view), 0.0, 1.0);
    float fresnel = 0.04 + 0.96 * pow(1.0 - facing, 5.0);
    if (studio && environment) {
        // The sky and ground mirrored in the glass, weighted by Fresnel; the key's glint in it.
        vec3 reflected = environmentLight(reflect(-view, n));
        vec3 color = toDisplay(mix(toLinear(partColor), reflected, fresnel));
        float alpha = clamp(0.015 + 0.6 * fresnel + 0.3 * max(max(color.r, color.g), color.b) * fresnel, 0.0, 0.9);
        fragColor = vec4(color, alpha);
        return;
    }
    float highlight = pow(max(dot(n, halfway), 0.0), 80.0);
    vec3 rimColor = blackBackground == 1 ? vec3(0.85, 0.92, 1.0) : partColor * vec3(0.55, 0.68, 0.80);
    vec3 color = mix(partColor, rimColor, fresnel) + vec3(highlight);
    // Four surfaces (two walls, each outer and inner) lie over the sand: each stays faint.
    float alpha = clamp(0.015 + 0.6 * fresnel + 0.5 * highlight, 0.0, 0.9);
    fragColor = vec4(color, alpha);
}

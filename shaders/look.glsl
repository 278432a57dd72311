// SPDX-License-Identifier: MIT
// The studio look (docs/rendering.md, Lighting to Glass environment), included by the grain,
// model and hull shaders so that every surface is lit, shadowed and tone mapped alike. Colours
// are sRGB-encoded; light is added in linear values and encoded again for the screen.

uniform bool studio;            // the studio lights; false: the thesis's look, none of this is read
uniform vec3 keyDirection;      // unit, world space, toward the warm key light
uniform vec3 keyColor;          // linear
uniform vec3 fillDirection;     // unit, toward the cool fill light
uniform vec3 fillColor;
uniform vec3 skyColor;          // ambient from straight above
uniform vec3 groundColor;       // ambient from straight below
uniform bool toneMapping;       // filmic curve; false: clamped
uniform bool environment;       // glass reflects the sky and ground
uniform bool keyShadows;
uniform sampler2DShadow shadowMap;
uniform mat4 lightMatrix;       // world to the shadow map's [0, 1] cube
uniform float shadowOffset;     // world units a receiver moves toward the light: one cell

vec3 toLinear(vec3 srgb) { return pow(srgb, vec3(2.2)); }

// Narkowicz's fit of the ACES filmic curve: keeps highlights from clipping to white and
// leaves every channel in [0, 1].
vec3 acesFilmic(vec3 x) {
    return clamp((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
}

vec3 toDisplay(vec3 linear) {
    vec3 mapped = toneMapping ? acesFilmic(linear) : clamp(linear, 0.0, 1.0);
    return pow(mapped, vec3(1.0 / 2.2));
}

// The share of the key light that reaches p (normal n): 1 lit, 0 in shadow. The point moves one
// cell toward the light and half a cell along its normal before the look-up, so a surface does
// not shadow itself (acne) while a grain one cell under another is still shadowed. One filtered
// look-up compares the 4 nearest texels and blends the answers: a soft edge a texel wide.
float keyLightReaching(vec3 p, vec3 n) {
    if (!keyShadows) return 1.0;
    vec3 q = p + keyDirection * shadowOffset + n * (0.5 * shadowOffset);
    vec3 s = (lightMatrix * vec4(q, 1.0)).xyz;
    if (any(lessThan(s, vec3(0.0))) || any(greaterThan(s, vec3(1.0)))) return 1.0;
    return texture(shadowMap, s);
}

// Linear light leaving a diffuse surface of linear albedo: a sky-to-ground ambient and the fill,
// both darkened by occlusion (1 open, less when crowded), and the key, darkened by its shadow
// and by half the occlusion (a grain deep in a crevice sees less of the key too).
vec3 studioLight(vec3 albedo, vec3 n, float occlusion, float keyReaching) {
    vec3 ambient = mix(groundColor, skyColor, 0.5 + 0.5 * n.y);
    float fill = max(dot(n, fillDirection), 0.0);
    float key = max(dot(n, keyDirection), 0.0);
    return albedo * ((ambient + fillColor * fill) * occlusion +
                     keyColor * (key * keyReaching * mix(1.0, occlusion, 0.5)));
}

// The soft environment glass reflects: a warm ground, a pale horizon, a blue sky overhead,
// and a bright patch toward the key light (linear values).
vec3 environmentLight(vec3 direction) {
    float up = direction.y;
    vec3 ground = vec3(0.30, 0.25, 0.20);
    vec3 horizon = vec3(0.95, 0.93, 0.90);
    vec3 sky = vec3(0.35, 0.55, 0.95);
    vec3 light = up < 0.0 ? mix(horizon, ground, smoothstep(0.0, 0.3, -up)) : mix(horizon, sky, smoothstep(0.0, 0.6, up));
    return light + keyColor * 0.5 * pow(max(dot(direction, keyDirection), 0.0), 64.0);
}

// SPDX-License-Identifier: MIT
// A grain's colour, the same in both grain shaders (grain.vert, grain_gpu.vert): unlit, the
// thesis's light near the camera, or the studio lights with occlusion and the key's shadow.
#include "look.glsl"

uniform bool lighting;
uniform vec3 lightPosition;     // the thesis's white point light slightly below the camera (§3.8)
uniform bool occlusion;         // ambient occlusion from the grain's occupied neighbours

// The light a grain's neighbourhood lets in, from its occlusion level ((occupied neighbours + 2)
// / 4, 0..7): up to 9 occupied (a grain on a peak, in the stream) is open; a grain on a flat
// surface (17) keeps 76%, one in a crevice (22-25) 52%, one enclosed (26, never seen) 40%.
float openness(int occlusionLevel) { return 1.0 - 0.6 * clamp(float(occlusionLevel - 2) / 5.0, 0.0, 1.0); }

vec3 shadeGrain(vec3 base, vec3 normal, int occlusionLevel, vec3 centre) {
    if (!lighting) return base;
    vec3 n = normalize(normal);
    if (!studio) {
        vec3 toLight = normalize(lightPosition - centre);
        float lambert = max(dot(n, toLight), 0.0);
        return base * (0.45 + 0.65 * lambert); // ambient keeps the side away from the light readable
    }
    float open = occlusion ? openness(occlusionLevel) : 1.0;
    return toDisplay(studioLight(toLinear(base), n, open, keyLightReaching(centre, n)));
}

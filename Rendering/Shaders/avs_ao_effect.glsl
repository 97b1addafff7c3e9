//AVS::Effect::Dec
// Volumetric ambient occlusion (ALGORITHM.md section 7): EA with the colour scaled by
// k_amb AO(x) + k_e, plus optional unshadowed direct light (compiled in, as AVS_DIRECT_LIGHT,
// only when its weight is above 0).
uniform sampler3D u_occlusion;      // on its own grid over the same box
uniform vec3 u_occlusionScale;      // data index -> its texture coordinate: index * scale + offset
uniform vec3 u_occlusionOffset;
uniform float u_ambientWeight;
uniform float u_emissionWeight;
uniform float u_directLightWeight;
uniform float u_albedo;
uniform float u_anisotropy;

#ifdef AVS_DIRECT_LIGHT
// Light j's unshadowed single scattering towards the camera at `world`.
vec3 DirectLight(int j, vec3 world, vec3 direction)
{
  vec3 propagation, irradiance;
  LightAt(j, world, propagation, irradiance);
  float mu = dot(propagation, -direction);
  return irradiance * (u_albedo * HenyeyGreenstein(mu, u_anisotropy));
}
#endif
//AVS::Effect::Sample
    {
      float ao = textureLod(u_occlusion, index * u_occlusionScale + u_occlusionOffset, 0.0).r;
      float weight = u_ambientWeight * ao + u_emissionWeight;
      vec3 c = here.rgb * weight;
#ifdef AVS_DIRECT_LIGHT
      if (here.a > 0.0)
      {
        vec3 world = origin + t * direction;
        vec3 direct = vec3(0.0);
#define AVS_DIRECT(j) direct += DirectLight(j, world, direction);
        AVS_FOR_EACH_LIGHT(AVS_DIRECT)
        c += here.rgb * direct * u_directLightWeight;
      }
#endif
      L += T * (1.0 - extinction) * c;
    }

//AVS::Lights::Dec
// The renderer's lights in world space (Rendering/Core/Lights.h): type 0 directional, 1
// positional; positional lights with a cone below 90 degrees are spots. The ray caster defines
// AVS_NUMBER_OF_LIGHTS (for AVS_FOR_EACH_LIGHT below), AVS_POSITIONAL_LIGHTS (a bit mask of the
// positional ones) and AVS_SPOT_LIGHTS when a spot is among them, and uploads positional lights
// other than spots with exponent 0 and no cone, so that the spot code leaves them unchanged.
// Known when the program is built, the lights' kinds cost no branch per sample, which matters
// where every branch of a shader runs (software rasterizers).
// AVS_FOR_EACH_LIGHT(F) expands to F(0) F(1) ... for the lights: loops unrolled by hand, with
// constant indices, since a compiler that does not unroll would index the arrays per sample.
#ifdef AVS_NUMBER_OF_LIGHTS
#if AVS_NUMBER_OF_LIGHTS > 7
#define AVS_FOR_EACH_LIGHT(F) F(0) F(1) F(2) F(3) F(4) F(5) F(6) F(7)
#elif AVS_NUMBER_OF_LIGHTS > 6
#define AVS_FOR_EACH_LIGHT(F) F(0) F(1) F(2) F(3) F(4) F(5) F(6)
#elif AVS_NUMBER_OF_LIGHTS > 5
#define AVS_FOR_EACH_LIGHT(F) F(0) F(1) F(2) F(3) F(4) F(5)
#elif AVS_NUMBER_OF_LIGHTS > 4
#define AVS_FOR_EACH_LIGHT(F) F(0) F(1) F(2) F(3) F(4)
#elif AVS_NUMBER_OF_LIGHTS > 3
#define AVS_FOR_EACH_LIGHT(F) F(0) F(1) F(2) F(3)
#elif AVS_NUMBER_OF_LIGHTS > 2
#define AVS_FOR_EACH_LIGHT(F) F(0) F(1) F(2)
#elif AVS_NUMBER_OF_LIGHTS > 1
#define AVS_FOR_EACH_LIGHT(F) F(0) F(1)
#elif AVS_NUMBER_OF_LIGHTS > 0
#define AVS_FOR_EACH_LIGHT(F) F(0)
#else
#define AVS_FOR_EACH_LIGHT(F)
#endif
#endif

uniform vec3 u_lightPosition[8];
uniform vec3 u_lightAxis[8];       // normalize(focal point - position)
uniform vec3 u_lightIrradiance[8]; // intensity x colour
uniform vec3 u_lightAttenuation[8];
uniform float u_lightConeCos[8];   // cos(cone angle); -2 for no cone
uniform float u_lightExponent[8];

#ifdef AVS_POSITIONAL_LIGHTS // effects with lights (not EA)
// Whether light j (a constant in the unrolled loops) is positional: bit j of the mask.
bool LightIsPositional(int j)
{
  return ((AVS_POSITIONAL_LIGHTS >> j) & 1) == 1;
}

// Light j at x: its propagation direction and its irradiance without shadowing (VTK's
// attenuation 1 / (a0 + a1 d + a2 d^2) and spot cone for positional lights).
void LightAt(int j, vec3 x, out vec3 propagation, out vec3 irradiance)
{
  if (!LightIsPositional(j))
  {
    propagation = u_lightAxis[j];
    irradiance = u_lightIrradiance[j];
  }
  else
  {
    vec3 d = x - u_lightPosition[j];
    float dist = length(d);
    propagation = dist > 0.0 ? d / dist : u_lightAxis[j];
    vec3 a = u_lightAttenuation[j];
    float att = a.x + a.y * dist + a.z * dist * dist;
    float scale = att > 0.0 ? 1.0 / att : 0.0;
#ifdef AVS_SPOT_LIGHTS
    float c = dot(u_lightAxis[j], propagation);
    scale = c >= u_lightConeCos[j] ? scale * exp2(u_lightExponent[j] * log2(max(c, 1e-30))) : 0.0;
#endif
    irradiance = u_lightIrradiance[j] * scale;
  }
}
#endif

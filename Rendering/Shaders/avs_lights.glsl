//AVS::Lights::Dec
// The renderer's lights in world space (Rendering/Core/Lights.h): type 0 directional, 1
// positional; positional lights with a cone below 90 degrees are spots.
uniform int u_numberOfLights;
uniform int u_lightPositional[8];
uniform vec3 u_lightPosition[8];
uniform vec3 u_lightAxis[8];       // normalize(focal point - position)
uniform vec3 u_lightIrradiance[8]; // intensity x colour
uniform vec3 u_lightAttenuation[8];
uniform float u_lightConeCos[8];   // cos(cone angle); -2 for no cone
uniform float u_lightExponent[8];

vec3 LightPropagation(int j, vec3 x)
{
  if (u_lightPositional[j] == 0)
  {
    return u_lightAxis[j];
  }
  vec3 d = x - u_lightPosition[j];
  float l = length(d);
  return l > 0.0 ? d / l : u_lightAxis[j];
}

vec3 LightIrradiance(int j, vec3 x)
{
  if (u_lightPositional[j] == 0)
  {
    return u_lightIrradiance[j];
  }
  vec3 d = x - u_lightPosition[j];
  float dist = length(d);
  vec3 a = u_lightAttenuation[j];
  float att = a.x + a.y * dist + a.z * dist * dist;
  float scale = att > 0.0 ? 1.0 / att : 0.0;
  if (u_lightConeCos[j] > -1.5)
  {
    float c = dist > 0.0 ? dot(u_lightAxis[j], d / dist) : 1.0;
    scale = c >= u_lightConeCos[j] ? scale * pow(max(c, 0.0), u_lightExponent[j]) : 0.0;
  }
  return u_lightIrradiance[j] * scale;
}

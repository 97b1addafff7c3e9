//AVS::Effect::Dec
// Ambient scattering (ALGORITHM.md section 6): emission (eq. 8.7) and the light that the ball of
// radius r around x' = x(t + r) scatters towards the camera (eqs. 8.8-8.9).
uniform sampler3D u_averaged;      // averaged sigma_t on the data's grid
uniform sampler3D u_lightVolumes0; // tube transmittance of lights 0-3 (rgba)
uniform sampler3D u_lightVolumes1; // lights 4-7
uniform vec3 u_lightVolumeDimensions;
uniform sampler2D u_table;         // A(theta, tau) for the current g and albedo
uniform vec2 u_tableSize;          // theta nodes, tau nodes
uniform float u_tableTauMaximum;
uniform float u_albedo;
uniform float u_ambientRadius;
uniform float u_emissionWeight;

// A(theta; tau) from the table slice; v is tau's table coordinate (see TableTauCoordinate).
float InScattering(float cosTheta, float v)
{
  float theta = acos(clamp(cosTheta, -1.0, 1.0));
  float u = sqrt(clamp(theta / PI, 0.0, 1.0));
  return texture(u_table, (vec2(u, v) * (u_tableSize - 1.0) + 0.5) / u_tableSize).r;
}

float TableTauCoordinate(float tau)
{
  return log(1.0 + clamp(tau, 0.0, u_tableTauMaximum)) / log(1.0 + u_tableTauMaximum);
}
//AVS::Effect::Sample
    L += T * (1.0 - u_albedo) * here.a * u_emissionWeight * dt * here.rgb;
    {
      vec3 ahead = index + u_ambientRadius * id;
      vec4 s2 = ClassifyAt(ahead);
      if (s2.a > 0.0)
      {
        float v = TableTauCoordinate(u_ambientRadius * texture(u_averaged, (ahead + 0.5) / u_dimensions).r);
        vec3 world = origin + (t + u_ambientRadius) * direction;
        // The tube transmittances of all lights at x', four to a texture fetch.
        vec3 f = ahead / (u_dimensions - 1.0);
        vec3 lc = (f * (u_lightVolumeDimensions - 1.0) + 0.5) / u_lightVolumeDimensions;
        vec4 tubes0 = texture(u_lightVolumes0, lc);
        vec4 tubes1 = u_numberOfLights > 4 ? texture(u_lightVolumes1, lc) : vec4(1.0);
        vec3 inscatter = vec3(0.0);
        for (int j = 0; j < u_numberOfLights; ++j)
        {
          float cosTheta = dot(LightPropagation(j, world), -direction);
          float tube = j < 4 ? tubes0[j] : tubes1[j - 4];
          inscatter += LightIrradiance(j, world) * (tube * InScattering(cosTheta, v));
        }
        L += T * s2.a * dt * s2.rgb * inscatter;
      }
    }

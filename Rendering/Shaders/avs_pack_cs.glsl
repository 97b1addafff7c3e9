#version 430
// Copies the tube transmittances of lights 0 and 1 (.rg of the first light-volume texture) into
// .ba of the ambient-scattering ray caster's volume texture (.r scalar, .g averaged sigma_t),
// when the light volumes share the data's grid: one fetch per sample then gives the scalar, the
// averaged extinction and two lights. A plain copy; nothing is resampled.
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

layout(rgba32f, binding = 0) uniform readonly image3D u_lights;
layout(rgba32f, binding = 1) uniform image3D u_volume;
uniform ivec3 u_dimensions;

void main()
{
  ivec3 v = ivec3(gl_GlobalInvocationID);
  if (any(greaterThanEqual(v, u_dimensions)))
  {
    return;
  }
  vec4 volume = imageLoad(u_volume, v);
  vec4 lights = imageLoad(u_lights, v);
  imageStore(u_volume, v, vec4(volume.rg, lights.rg));
}

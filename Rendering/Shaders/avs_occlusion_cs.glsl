#version 430
// Local ambient occlusion (ALGORITHM.md section 7) on the GPU: for each voxel the mean over K
// directions of exp(-integral of sigma_t over [0, R]), midpoint rule with n steps. The CPU
// version is Rendering/Core/AmbientOcclusion.cxx, which the tests hold this pass against.
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

layout(r32f, binding = 0) uniform image3D u_target;
uniform sampler3D u_extinction; // sigma_t on the data grid (texel centres = voxels)
uniform ivec3 u_dimensions;       // of the data grid
uniform ivec3 u_targetDimensions; // of the occlusion grid (same box, at most as fine)
uniform float u_border;           // the volume box reaches this far beyond the lattice (cell data)
uniform int u_directions;
uniform int u_steps;
uniform float u_step;              // R / n, world units
uniform vec3 u_offsets[256];       // per direction: the index offset of one step along it

void main()
{
  ivec3 voxel = ivec3(gl_GlobalInvocationID);
  if (any(greaterThanEqual(voxel, u_targetDimensions)))
  {
    return;
  }
  vec3 n = vec3(u_dimensions);
  // The grid point's continuous index on the data grid.
  vec3 base = vec3(voxel) * (n - 1.0) / max(vec3(u_targetDimensions) - 1.0, vec3(1.0));
  float sum = 0.0;
  for (int k = 0; k < u_directions; ++k)
  {
    float optical = 0.0;
    for (int s = 0; s < u_steps; ++s)
    {
      vec3 index = base + (float(s) + 0.5) * u_offsets[k];
      // Inside the volume's box: the lattice widened by the border (cell data), where the
      // texture clamps to the lattice's faces.
      if (all(greaterThanEqual(index, vec3(-u_border - 1e-6))) &&
        all(lessThanEqual(index, n - 1.0 + u_border + 1e-6)))
      {
        optical += texture(u_extinction, (index + 0.5) / n).r;
      }
    }
    sum += exp(-optical * u_step);
  }
  imageStore(u_target, voxel, vec4(sum / float(u_directions)));
}

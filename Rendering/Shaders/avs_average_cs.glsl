#version 430
// The averaged extinction on the GPU (ALGORITHM.md section 3; the CPU version is
// Rendering/Core/AveragedExtinction.cxx, which the tests hold this pass against).
// Pass 0 classifies the scalars into sigma_t; passes 1-3 are the box sums along x, y and z, one
// invocation per line with a running window sum in double precision (the per-line summed-area
// table); pass 3 also divides by the full box count, so voxels outside count as 0, and writes
// the result twice: alone (for the light-volume pass) and beside the voxel's scalar in the ray
// caster's volume texture (.r scalar, .g averaged sigma_t, .ba lights 0 and 1 once
// avs_pack_cs.glsl has run), so that one fetch per sample gives them all.
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

layout(r32f, binding = 0) uniform readonly image3D u_input;
layout(r32f, binding = 1) uniform writeonly image3D u_output;
layout(rgba32f, binding = 2) uniform writeonly image3D u_final; // pass 3
uniform int u_pass;
uniform ivec3 u_dimensions;
uniform int u_halfWidth;     // k along this pass's axis
uniform float u_inverseCount; // 1 / prod(2 k_a + 1), applied in the last pass

uniform sampler3D u_scalars;  // pass 0
uniform sampler1D u_transfer; // pass 0: opacity in .a over u_scalarRange
uniform vec2 u_scalarRange;
uniform float u_transferSize;
uniform float u_unitDistance;

void main()
{
  if (u_pass == 0)
  {
    ivec3 v = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(v, u_dimensions)))
      return;
    float s = texelFetch(u_scalars, v, 0).r;
    float c = clamp((s - u_scalarRange.x) / (u_scalarRange.y - u_scalarRange.x), 0.0, 1.0);
    float alpha = min(texture(u_transfer, (c * (u_transferSize - 1.0) + 0.5) / u_transferSize).a,
      1.0 - 1e-6);
    imageStore(u_output, v, vec4(alpha > 0.0 ? -log(1.0 - alpha) / u_unitDistance : 0.0));
    return;
  }
  // The line: this pass's axis varies, the two others come from the invocation.
  int axis = u_pass - 1;
  ivec2 other = ivec2(gl_GlobalInvocationID.xy);
  ivec3 dims = u_dimensions;
  ivec2 otherDims = axis == 0 ? dims.yz : (axis == 1 ? dims.xz : dims.xy);
  if (any(greaterThanEqual(other, otherDims)))
    return;
  int n = dims[axis];
  int k = u_halfWidth;
  ivec3 base = axis == 0 ? ivec3(0, other.x, other.y)
                         : (axis == 1 ? ivec3(other.x, 0, other.y) : ivec3(other.x, other.y, 0));
  ivec3 step = ivec3(axis == 0 ? 1 : 0, axis == 1 ? 1 : 0, axis == 2 ? 1 : 0);
  double sum = 0.0;
  for (int j = 0; j <= min(k, n - 1); ++j)
  {
    sum += double(imageLoad(u_input, base + j * step).r);
  }
  for (int i = 0; i < n; ++i)
  {
    if (u_pass == 3)
    {
      ivec3 v = base + i * step;
      float averaged = float(sum) * u_inverseCount;
      imageStore(u_output, v, vec4(averaged));
      imageStore(u_final, v, vec4(texelFetch(u_scalars, v, 0).r, averaged, 1.0, 1.0));
    }
    else
    {
      imageStore(u_output, base + i * step, vec4(float(sum)));
    }
    int add = i + k + 1;
    int remove = i - k;
    if (add < n)
      sum += double(imageLoad(u_input, base + add * step).r);
    if (remove >= 0)
      sum -= double(imageLoad(u_input, base + remove * step).r);
  }
}

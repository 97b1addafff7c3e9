#version 430
// The averaged extinction on the GPU (ALGORITHM.md section 3; the CPU version is
// Rendering/Core/AveragedExtinction.cxx, AverageExtinctionOn, which the tests hold this pass
// against), stored on the light volumes' grid (the data's grid or a coarser one over the same
// box).
// Pass 0 classifies the scalars into sigma_t on the data grid. Passes 1-3 take the box sums
// along x, y and z: one invocation per line, a running window sum in double precision (the
// per-line summed-area table) over the line's voxels, written at the target grid's points along
// that axis by linear interpolation between the two voxels around each (so each pass shrinks
// its axis to the target's size, and the three together give the data-grid average
// interpolated trilinearly). Pass 3 also divides by the full box count, so voxels outside count
// as 0; its result is what the light-volume pass and the ray caster sample. The
// classification's defines come before this.
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

layout(r32f, binding = 0) uniform readonly image3D u_input;
layout(r32f, binding = 1) uniform writeonly image3D u_output;
uniform int u_pass;
uniform ivec3 u_dimensions;  // of u_input (pass 0: of the data)
uniform int u_targetLength;  // points of the target grid along this pass's axis
uniform int u_halfWidth;     // k along this pass's axis
uniform float u_inverseCount; // 1 / prod(2 k_a + 1), applied in the last pass

// u_scalars (pass 0) is declared by the classification.
// Pass 0: Classify(s), the ray caster's classification (avs_classify.glsl), and 0 outside
// the clipping planes and cropping (avs_clip.glsl).
//AVS::Classify::Dec
//AVS::Clip::Dec

void Store(ivec3 v, double sum)
{
  imageStore(u_output, v, vec4(u_pass == 3 ? float(sum) * u_inverseCount : float(sum)));
}

void main()
{
  // Pass 0 works voxel by voxel, one invocation per column along z: on a software
  // rasterizer one invocation per voxel costs about twice as much (measured with llvmpipe).
  if (u_pass == 0)
  {
    ivec2 xy = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(xy, u_dimensions.xy)))
      return;
    for (int z = 0; z < u_dimensions.z; ++z)
    {
      ivec3 v = ivec3(xy, z);
      vec3 coordinate = (vec3(v) + 0.5) / vec3(u_dimensions);
      imageStore(u_output, v,
        vec4(Classify(texelFetch(u_scalars, v, 0), coordinate).a * ClipInside(vec3(v), true)));
    }
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
  // Target point o sits at voxel position o * ratio along the axis.
  double ratio = u_targetLength > 1 ? double(n - 1) / double(u_targetLength - 1) : 0.0;
  double sum = 0.0;
  for (int j = 0; j <= min(k, n - 1); ++j)
  {
    sum += double(imageLoad(u_input, base + j * step).r);
  }
  double previous = sum; // the window sum at voxel i - 1
  int o = 0;
  for (int i = 0; i < n && o < u_targetLength; ++i)
  {
    // Target points in (i - 1, i]: at most two (the ratio is at least 1).
    for (int e = 0; e < 2; ++e)
    {
      double position = double(o) * ratio;
      if (o < u_targetLength && (position <= double(i) || i == n - 1))
      {
        double w = clamp(position - double(i - 1), 0.0, 1.0);
        Store(base + o * step, previous + (sum - previous) * w);
        ++o;
      }
    }
    previous = sum;
    int add = i + k + 1;
    int remove = i - k;
    if (add < n)
      sum += double(imageLoad(u_input, base + add * step).r);
    if (remove >= 0)
      sum -= double(imageLoad(u_input, base + remove * step).r);
  }
}

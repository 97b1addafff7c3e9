#version 430
// The averaged extinction on the GPU (ALGORITHM.md section 3; the CPU version is
// Rendering/Core/AveragedExtinction.cxx, AverageExtinctionOn, which the tests hold this pass
// against), stored on the light volumes' grid (the data's grid or a coarser one over the same
// box).
// Passes 1-3 take the box sums of sigma_t along x, y and z (pass 1 classifies the scalars as it
// reads them, so sigma_t on the data grid is never stored): one invocation per line, a running window sum in double precision (the
// per-line summed-area table) over the line's voxels, written at the target grid's points along
// that axis by linear interpolation between the two voxels around each (so each pass shrinks
// its axis to the target's size, and the three together give the data-grid average
// interpolated trilinearly). Pass 3 also divides by the full box count, so voxels outside count
// as 0; its result is what the light-volume pass and the ray caster sample. Passes 1 and 2 run
// slab by slab along z (u_zOffset: the slab's first slice), so that pass 1's result, the
// largest of the intermediate grids, is held for one slab at a time. The classification's
// defines come before this, and AVS_AVERAGE_CLASSIFY in pass 1's program: passes 2 and 3 have
// their own without the classification, since a software rasterizer runs both sides of a
// branch (pass 1's texture fetches cost passes 2 and 3 as much again when a uniform chose).
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

layout(r32f, binding = 0) uniform readonly image3D u_input;
layout(r32f, binding = 1) uniform writeonly image3D u_output;
uniform int u_pass;
uniform ivec3 u_dimensions;  // of u_input (pass 1: of the data)
uniform int u_targetLength;  // points of the target grid along this pass's axis
uniform int u_halfWidth;     // k along this pass's axis
uniform float u_inverseCount; // 1 / prod(2 k_a + 1), applied in the last pass
uniform int u_zOffset;       // passes 1 and 2: the slab's first slice in the data's z

// Pass 1 keeps the window's classified values in a ring of AVS_AVERAGE_RING entries (a power of
// two above 2 k + 1, the program built for it), so that each voxel is classified once, entering
// the window, and its value taken out of the sum from the ring when it leaves; with a window too
// wide for a ring (AVS_AVERAGE_RING 0) it is classified again when it leaves.
#ifdef AVS_AVERAGE_CLASSIFY
#if AVS_AVERAGE_RING > 0
#define AVS_AVERAGE_WINDOW
#endif
#endif
#ifdef AVS_AVERAGE_WINDOW
float g_window[AVS_AVERAGE_RING];
#define AVS_AVERAGE_KEEP(i, value) g_window[(i) & (AVS_AVERAGE_RING - 1)] = value
#define AVS_AVERAGE_KEPT(i, v) g_window[(i) & (AVS_AVERAGE_RING - 1)]
#else
#define AVS_AVERAGE_KEEP(i, value)
#define AVS_AVERAGE_KEPT(i, v) Input(v)
#endif

// u_scalars (pass 1) is declared by the classification.
// Pass 1's input: Classify(s), the ray caster's classification (avs_classify.glsl), and 0
// outside the clipping planes and cropping (avs_clip.glsl).
//AVS::Classify::Dec
//AVS::Clip::Dec

void Store(ivec3 v, double sum)
{
  // Pass 2 writes the slab into the whole of its target; pass 1 into the slab's grid.
  ivec3 at = u_pass == 2 ? v + ivec3(0, 0, u_zOffset) : v;
  imageStore(u_output, at, vec4(u_pass == 3 ? float(sum) * u_inverseCount : float(sum)));
}

// sigma_t at voxel v: classified from the scalars in pass 1, the previous pass's result after.
float Input(ivec3 v)
{
#ifdef AVS_AVERAGE_CLASSIFY
  ivec3 w = v + ivec3(0, 0, u_zOffset); // the voxel in the data
  vec3 coordinate = (vec3(w) + 0.5) / vec3(textureSize(u_scalars, 0));
  return Classify(texelFetch(u_scalars, w, 0), coordinate).a * ClipInside(vec3(w), true);
#else
  return imageLoad(u_input, v).r;
#endif
}

void main()
{
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
    float value = Input(base + j * step);
    AVS_AVERAGE_KEEP(j, value);
    sum += double(value);
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
    {
      float value = Input(base + add * step);
      AVS_AVERAGE_KEEP(add, value);
      sum += double(value);
    }
    if (remove >= 0)
      sum -= double(AVS_AVERAGE_KEPT(remove, base + remove * step));
  }
}

//VTK::System::Dec
// Ray casting framework of the three mappers (ALGORITHM.md sections 2, 6 and 7): one ray per
// pixel from the inverse view-projection (camera inside the volume and parallel projection
// included), clipped to the volume box and to the opaque geometry's depth, marched front to back
// in equal steps, with the mapper's effect snippet (declarations, per-ray set-up, per-pair and
// per-sample code) put in at the four effect markers below. Each sample (RaySample) fetches one
// texel of the scalars (AVS_VOLUME_TEXTURE) and classifies it (avs_classify.glsl). An effect may define
// AVS_EFFECT_TERMINATION (then its bool EffectContinues(float T, int i) ends the ray),
// AVS_SAMPLE_PAIRS (with EffectContinues and AVS_SAMPLE_GROUP, 2 or 4: the loop takes that many
// samples per iteration, classifies them, then runs the effect's per-group code, which sees the
// group's first index `pair` and whether one of its samples has extinction, g_pairMaterial),
// AVS_EFFECT_KEEPS_TRANSMITTANCE (then it updates T itself, as the blend modes other than
// composite do), AVS_EFFECT_OUTPUT (then vec4 EffectOutput(vec3 L, float T) gives the
// premultiplied pixel) and AVS_EFFECT_LEAP (then void EffectLeap(int from, int to) learns of
// the empty samples [from, to) that empty-space skipping leapt over: avs_skip.glsl). The CPU
// reference (Rendering/Core/ReferenceRenderer.cxx) computes the same sums in double precision.
//
// Distances: t runs along the world ray (positions, depth); the integration step dt is in data
// units, the vtkVolume's coordinates before its matrix (u_spacing turns an index step into
// them), as vtkGPUVolumeRayCastMapper integrates opacity: a scaled vtkVolume renders as the
// unscaled one magnified. Sample distance, unit distance and ambient radius are data units.

//VTK::Output::Dec

in vec2 texCoord; // position in the viewport, [0, 1]^2 (from the quad's vertex shader)

uniform mat4 u_ndcToWorld;   // inverse of the camera's world -> NDC
uniform mat4 u_worldToIndex; // world -> continuous voxel index of the data
uniform sampler2D u_depth;   // depth of what the renderer drew before
uniform vec3 u_dimensions;   // voxels per axis
uniform vec3 u_spacing;      // data units per index step, per axis
uniform float u_border;      // the box reaches this many voxels beyond them (cell data: 0.5)
uniform float u_sampleDistance; // data units
uniform float u_termination;    // stop when T falls below
uniform int u_jitter;           // 1: jitter the first sample per pixel

const float PI = 3.14159265358979;

// Classify(texel, coordinate): colour and extinction of a sample (avs_classify.glsl), which
// declares the volume texture AVS_VOLUME_TEXTURE.
//AVS::Classify::Dec

// Henyey-Greenstein, mu = cosine between the propagation directions of incoming and scattered
// light (same convention as Rendering/Core/PhaseFunction.h).
float HenyeyGreenstein(float mu, float g)
{
  float d = 1.0 + g * g - 2.0 * g * mu;
  return (1.0 - g * g) / (4.0 * PI * d * sqrt(d));
}

//AVS::Lights::Dec

// DisplayTransform(L): exposure and tone curve (avs_display.glsl), applied where the ray ends
// unless the pass goes through the image sampler's target, whose compositing applies it to the
// sum of the bricks' passes (u_displayInRay 0).
//AVS::Display::Dec
uniform int u_displayInRay;

// ClipRay, ClipInside, AVS_CROP: clipping planes and cropping (avs_clip.glsl).
//AVS::Clip::Dec

#ifdef AVS_BRICKED
// A split volume (Rendering/OpenGL/vtkAVSBricks.h) is drawn one brick per pass, back to front:
// the brick's owned box [u_brickLow, u_brickHigh) (continuous index) and its texture's first
// voxel and size. Each pass takes the unsplit ray's samples that lie in the owned box. (Here,
// after //AVS::Classify::Dec, where the defines go.)
uniform vec3 u_brickLow;
uniform vec3 u_brickHigh;
uniform vec3 u_brickOrigin;
uniform vec3 u_brickDimensions;
// The volume texture coordinate of a continuous index (texel centres on the voxels).
vec3 VolumeCoordinate(vec3 index)
{
  return (index - u_brickOrigin + 0.5) / u_brickDimensions;
}
#else
vec3 VolumeCoordinate(vec3 index)
{
  return (index + 0.5) / u_dimensions;
}
#endif

// The ray's values, shared by main and RaySample (a function, so that a loop may take two
// samples per iteration without a second copy of the sample's code). main sets them all before
// the first sample; the initial values only tell the compiler so.
vec3 origin = vec3(0.0), direction = vec3(0.0); // world ray
vec3 io = vec3(0.0), id = vec3(0.0);            // index(t) = io + t * id for world distance t
float t0 = 0.0, dtWorld = 0.0, dt = 0.0, offset = 0.0;
int steps = 0;
int raySteps = 0; // the unsplit ray's samples (a brick's pass keeps only its own in steps)
#ifdef AVS_BRICKED
int brickFirst = 0;
#endif
vec3 firstCoordinate = vec3(0.0), stepCoordinate = vec3(0.0);
bool g_pairMaterial = false; // AVS_SAMPLE_PAIRS: whether a sample of the pair has sigma_t > 0
vec3 L = vec3(0.0);  // radiance so far
float T = 1.0; // transmittance so far

//AVS::Effect::Dec

// Leap(i): empty-space skipping where AVS_SKIP is defined (avs_skip.glsl).
//AVS::Skip::Dec

float Hash(vec2 p)
{
  return fract(sin(dot(p, vec2(12.9898, 78.233))) * 43758.5453);
}

// Sample i of the ray: where it lies, its volume texel (`voxel`) and its classification.
vec4 ClassifySample(int i, out vec4 voxel)
{
  float t = t0 + (float(i) + offset) * dtWorld;
  vec3 index = io + t * id;
  vec3 coordinate = firstCoordinate + float(i) * stepCoordinate;
#ifdef AVS_SURFACE_PACKED
  // (The surfaces' texel, which holds the scalar in A: `voxel` is that texel.)
  voxel = textureLod(u_surfaces, coordinate, 0.0);
  vec4 here = Classify(PackedScalar(voxel), coordinate);
#else
  voxel = textureLod(AVS_VOLUME_TEXTURE, coordinate, 0.0);
  vec4 here = Classify(voxel, coordinate);
#endif
  AVS_CROP(here, index);
  return here;
}

// Sample i of the ray, classified (`here`, from its texel `voxel`): the effect's light and the
// transmittance.
void RaySampleClassified(int i, vec4 voxel, vec4 here)
{
  float t = t0 + (float(i) + offset) * dtWorld;
  vec3 index = io + t * id;
  vec3 coordinate = firstCoordinate + float(i) * stepCoordinate;
  float extinction = exp(-here.a * dt);
  //AVS::Effect::Sample
#ifndef AVS_EFFECT_KEEPS_TRANSMITTANCE
  if (T >= u_termination)
    T *= extinction;
#endif
}

// Sample i of the ray: its classification, the effect's light and the transmittance.
void RaySample(int i)
{
  vec4 voxel;
  vec4 here = ClassifySample(i, voxel);
  RaySampleClassified(i, voxel, here);
}

void main()
{
  vec2 ndc = texCoord * 2.0 - 1.0;
  vec4 nearPoint = u_ndcToWorld * vec4(ndc, -1.0, 1.0);
  vec4 farPoint = u_ndcToWorld * vec4(ndc, 1.0, 1.0);
  origin = nearPoint.xyz / nearPoint.w;
  direction = normalize(farPoint.xyz / farPoint.w - origin);

  // The ray in index space: index(t) = io + t * id for world distance t.
  io = (u_worldToIndex * vec4(origin, 1.0)).xyz;
  id = (u_worldToIndex * vec4(direction, 0.0)).xyz;
  vec3 lo = (-u_border - io) / id;
  vec3 hi = (u_dimensions - 1.0 + u_border - io) / id;
  vec3 tmin = min(lo, hi);
  vec3 tmax = max(lo, hi);
  t0 = max(max(max(tmin.x, tmin.y), tmin.z), 0.0);
  float t1 = min(min(tmax.x, tmax.y), tmax.z);

  // Opaque geometry drawn before ends the ray.
  float depth = texture(u_depth, texCoord).r;
  if (depth < 1.0)
  {
    vec4 p = u_ndcToWorld * vec4(ndc, 2.0 * depth - 1.0, 1.0);
    t1 = min(t1, dot(p.xyz / p.w - origin, direction));
  }
#ifdef AVS_CLIPPING
  // Clipping planes and the box of the kept cropping regions shorten the ray.
  if (!ClipRay(io, id, t0, t1))
  {
    discard;
  }
#endif
  if (!(t1 > t0))
  {
    discard;
  }
  // Steps of at most the sample distance in data units; dtWorld along the world ray.
  float dataPerWorld = length(id * u_spacing);
  steps = max(1, int(ceil((t1 - t0) * dataPerWorld / u_sampleDistance - 1e-4)));
  raySteps = steps;
  dtWorld = (t1 - t0) / float(steps);
  dt = dtWorld * dataPerWorld;
  offset = u_jitter == 1 ? Hash(gl_FragCoord.xy) : 0.5;
#ifdef AVS_BRICKED
  // The samples t0 + (i + offset) dtWorld of the unsplit ray in the brick's owned box: i in
  // [brickFirst, brickLast). Neighbouring bricks compute their shared face's crossing from the
  // same plane, so every sample falls in exactly one brick. The ray then starts at brickFirst.
  // (Clamped as floats: a ray parallel to a face has infinite crossings.)
  vec3 blo = (u_brickLow - io) / id;
  vec3 bhi = (u_brickHigh - io) / id;
  vec3 bmin = min(blo, bhi);
  vec3 bmax = max(blo, bhi);
  float b0 = max(max(bmin.x, bmin.y), bmin.z);
  float b1 = min(min(bmax.x, bmax.y), bmax.z);
  brickFirst = int(clamp(ceil((b0 - t0) / dtWorld - offset), 0.0, float(steps)));
  int brickLast = int(clamp(ceil((b1 - t0) / dtWorld - offset), 0.0, float(steps)));
  if (brickLast <= brickFirst)
  {
    discard;
  }
  t0 += float(brickFirst) * dtWorld;
  steps = brickLast - brickFirst;
  vec3 inverseDimensions = 1.0 / u_brickDimensions;
  firstCoordinate = VolumeCoordinate(io + (t0 + offset * dtWorld) * id);
#else
  // Per-ray constants: the volume texture coordinate of sample i is first + i * step (texel
  // centres on the voxels), and the transfer-function coordinates are affine in the scalar.
  vec3 inverseDimensions = 1.0 / u_dimensions;
  firstCoordinate = (io + (t0 + offset * dtWorld) * id + 0.5) * inverseDimensions;
#endif
  stepCoordinate = dtWorld * id * inverseDimensions;

  L = vec3(0.0);
  T = 1.0;
  //AVS::Effect::Init

#ifdef AVS_SAMPLE_PAIRS
  // AVS_SAMPLE_GROUP (2 or 4) samples per iteration, which share the effect's per-group work
  // (its Pair snippet): the unsplit ray's samples G m to G m + G - 1 (a brick that starts inside
  // a group starts with its part of it: the iteration's samples before the brick are classified
  // as its first sample, and add nothing).
#ifdef AVS_BRICKED
  int firstPair = -(brickFirst & (AVS_SAMPLE_GROUP - 1));
#else
  int firstPair = 0;
#endif
  for (int pair = firstPair; pair < steps; pair += AVS_SAMPLE_GROUP)
  {
#ifdef AVS_SKIP
    if (pair >= g_checkFrom)
    {
      // Over the empty cells to the group of the first sample that may have material.
      int j = Leap(pair);
      if (j >= steps)
        break;
      pair = max(pair, j - ((j - firstPair) & (AVS_SAMPLE_GROUP - 1)));
    }
#endif
    if (!EffectContinues(T, max(pair, 0)))
      break;
    // The group's samples classified first: the effect's Pair snippet knows whether the group
    // has material (g_pairMaterial).
    vec4 voxelA, voxelB;
    vec4 hereA = ClassifySample(max(pair, 0), voxelA);
    vec4 hereB = ClassifySample(clamp(pair + 1, 0, steps - 1), voxelB);
#if AVS_SAMPLE_GROUP == 4
    vec4 voxelC, voxelD;
    vec4 hereC = ClassifySample(clamp(pair + 2, 0, steps - 1), voxelC);
    vec4 hereD = ClassifySample(clamp(pair + 3, 0, steps - 1), voxelD);
    g_pairMaterial = hereA.a > 0.0 || hereB.a > 0.0 || hereC.a > 0.0 || hereD.a > 0.0;
#else
    g_pairMaterial = hereA.a > 0.0 || hereB.a > 0.0;
#endif
    //AVS::Effect::Pair
    if (pair >= 0)
    {
      RaySampleClassified(pair, voxelA, hereA);
    }
    // (Each later sample ends the ray as the single loop does: with a look-ahead of 0 steps the
    // test reads the sample before's ring entry.)
    if (pair + 1 >= 0 && pair + 1 < steps)
    {
      if (!EffectContinues(T, pair + 1))
        break;
      RaySampleClassified(pair + 1, voxelB, hereB);
    }
#if AVS_SAMPLE_GROUP == 4
    if (pair + 2 >= 0 && pair + 2 < steps)
    {
      if (!EffectContinues(T, pair + 2))
        break;
      RaySampleClassified(pair + 2, voxelC, hereC);
    }
    if (pair + 3 < steps)
    {
      if (!EffectContinues(T, pair + 3))
        break;
      RaySampleClassified(pair + 3, voxelD, hereD);
    }
#endif
  }
#else
  for (int i = 0; i < steps; ++i)
  {
#ifdef AVS_SKIP
    if (i >= g_checkFrom)
    {
      // Over the empty cells; the test below then sees T after them, as the unleapt ray would.
      i = Leap(i);
      if (i >= steps)
        break;
    }
#endif
#ifdef AVS_EFFECT_TERMINATION
    // The effect decides (it may still have light to add after T fell below the threshold).
    if (!EffectContinues(T, i))
      break;
#else
    if (T < u_termination)
      break;
#endif
    RaySample(i);
  }
#endif
#ifdef AVS_EFFECT_OUTPUT
  vec4 result = EffectOutput(L, T);
#else
  vec4 result = vec4(L, 1.0 - T);
#endif
  if (u_displayInRay == 1)
  {
    result.rgb = DisplayTransform(result.rgb);
  }
  gl_FragData[0] = result;
}

/**
 * @class   vtkAVSRenderPasses
 * @brief   how the module's ray caster takes part in VTK's render passes (private)
 *
 * The ray caster draws one full-screen pass composited over what the renderer drew. VTK's render
 * passes call the mappers in other circumstances than the renderer's own sequence, and this
 * class holds what the ray caster does about them:
 *
 * - Inside a pass's own framebuffer (vtkToneMappingPass, vtkSSAOPass, a vtkCameraPass given a
 *   framebuffer, vtkDualDepthPeelingPass) the viewport is the pass's, not the renderer's place in
 *   the window: the volume is drawn into the current viewport (Locate), and the depth of the
 *   opaque geometry is read where the renderer's picture lies in the read framebuffer.
 * - Passes attached to the volume's property keys (vtkOpenGLRenderPass::RenderPasses()) get their
 *   SetShaderParameters called, as VTK's mappers do: vtkSSAOPass then lets the volume write the
 *   colour target only, not its position and normal targets.
 * - vtkDualDepthPeelingPass with volumes (renderer UseDepthPeelingForVolumes, translucent
 *   geometry present) calls the volumes once before peeling and again in every peel. The ray
 *   caster cannot peel: it draws the whole volume in the first call into the pass's front
 *   accumulation target, which the pass then blends the translucent layers behind, and nothing in
 *   the later calls (Role). The picture is the one the renderer gives without
 *   UseDepthPeelingForVolumes: the volume composited over the translucent geometry.
 * - Under vtkToneMappingPass (the renderer's pass, or a delegate of camera, image-processing,
 *   SSAA, sequence and render-steps passes below it; ParaView's view tone mapping, in one
 *   process, is tested) the pass maps the whole
 *   picture from its float framebuffer: the volume hands over its radiance linear, with its
 *   exposure but without its own tone curve, so that nothing is mapped twice (UnderToneMapping).
 * - VTK's passes leave OpenGL errors pending in release builds (glCopyTexImage2D from a
 *   multisampled framebuffer in FXAA and depth peeling, for instance). The ray caster discards
 *   them before its own calls (DiscardErrors) and checks only its own.
 */
#ifndef vtkAVSRenderPasses_h
#define vtkAVSRenderPasses_h

#include <array>

class vtkAbstractMapper;
class vtkOpenGLRenderWindow;
class vtkOpenGLState;
class vtkProp;
class vtkRenderer;
class vtkShaderProgram;

class vtkAVSRenderPasses
{
public:
  /// What a mapper does when it is called now.
  enum class Role
  {
    Composite,    ///< draw the volume over the framebuffer (no peeling pass, or none with volumes)
    PeelingFront, ///< vtkDualDepthPeelingPass's first volumetric call: draw into its front target
    Skip          ///< vtkDualDepthPeelingPass's later volumetric calls: draw nothing
  };
  static Role RoleOf(vtkProp* prop, vtkAbstractMapper* mapper);

  /// Calls SetShaderParameters of the passes attached to the prop (vtkOpenGLRenderPass protocol).
  static void SetShaderParameters(vtkProp* prop,
    vtkAbstractMapper* mapper,
    vtkShaderProgram* program);

  /// Whether a vtkToneMappingPass is among the renderer's passes (its pass, and the delegates and
  /// sequences below it: camera, image-processing, SSAA, sequence and render-steps passes).
  static bool UnderToneMapping(vtkRenderer* renderer);

  /// Reads and drops the OpenGL errors left pending by others (at most 16); returns how many.
  static int DiscardErrors();

  /// Where to draw and where to read the depth.
  struct Region
  {
    std::array<int, 4> Draw{ 0, 0, 1, 1 }; ///< x, y, width, height: the current viewport
    std::array<int, 2> ReadOrigin{ 0, 0 }; ///< lower left corner in the read framebuffer
  };
  /// The current viewport; the read origin is the viewport's when the read framebuffer is the
  /// draw framebuffer, else the renderer's tiled origin in the window's own framebuffers and
  /// (0, 0) in a pass's (which are viewport-sized).
  static Region Locate(vtkOpenGLRenderWindow* window, vtkRenderer* renderer);

  /// While alive: blending on with GL_FUNC_ADD and (1, 1 - source alpha), depth test, depth
  /// writes and face culling off; restores all of them.
  class ScopedCompositing
  {
  public:
    explicit ScopedCompositing(vtkOpenGLState* state);
    ~ScopedCompositing();
    ScopedCompositing(const ScopedCompositing&) = delete;
    ScopedCompositing& operator=(const ScopedCompositing&) = delete;

  private:
    vtkOpenGLState* State;
    bool Blend, DepthTest, Cull;
    unsigned char DepthMask;
    int Equation[2];
    int Function[4];
  };

  /// While alive: the fragment output goes to one draw buffer alone, the `which`-th of those
  /// active (0; 1 for Role::PeelingFront: vtkDualDepthPeelingPass's front target), not to the
  /// others (vtkSSAOPass's position and normal targets); restores the draw buffers.
  class ScopedDrawBuffer
  {
  public:
    ScopedDrawBuffer(vtkOpenGLState* state, int which);
    ~ScopedDrawBuffer();
    ScopedDrawBuffer(const ScopedDrawBuffer&) = delete;
    ScopedDrawBuffer& operator=(const ScopedDrawBuffer&) = delete;

  private:
    static constexpr int MaximumBuffers = 8;
    static void SetDrawBuffers(vtkOpenGLState* state, int count, unsigned int* buffers);
    vtkOpenGLState* State;
    unsigned int Buffers[MaximumBuffers] = {};
    int Count = 0;
    bool Changed = false;
  };
};

#endif

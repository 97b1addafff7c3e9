// The render events a VTK user observes for progress and timing: every mapper fires
// vtkCommand::VolumeMapperRenderStartEvent and VolumeMapperRenderEndEvent around its work, once
// per render, as vtkGPUVolumeRayCastMapper does (the same script runs with VTK's mapper beside
// ours): the start before the frame is drawn, the end after it, a refused render (bad input, an
// unsupported blend mode) still one pair, and one pair per frame inside
// vtkDualDepthPeelingPass's volume peeling, which calls the mapper more than once a frame.
#include "MapperTestScene.h"
#include "TestErrorObserver.h"

#include "vtkActor.h"
#include "vtkAmbientOcclusionVolumeMapper.h"
#include "vtkAmbientScatteringVolumeMapper.h"
#include "vtkCallbackCommand.h"
#include "vtkEmissionAbsorptionVolumeMapper.h"
#include "vtkGPUVolumeRayCastMapper.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkSphereSource.h"

#include <iostream>
#include <string>
#include <vector>

namespace
{
/// The events a mapper fired, in order ('S' start, 'E' end), and the frames it had drawn at
/// each (our mappers' NumberOfRenderedFrames; -1 for VTK's).
struct EventLog
{
  std::string Events;
  std::vector<int> Frames;
  vtkVolumeMapper* Mapper = nullptr;
};

void Record(vtkObject*, unsigned long event, void* clientData, void*)
{
  auto* log = static_cast<EventLog*>(clientData);
  log->Events += event == vtkCommand::VolumeMapperRenderStartEvent ? 'S' : 'E';
  auto* ours = vtkAVSVolumeMapper::SafeDownCast(log->Mapper);
  log->Frames.push_back(ours ? ours->GetNumberOfRenderedFrames() : -1);
}

struct Scene
{
  vtkNew<vtkRenderWindow> Window;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkVolume> Volume;
  vtkNew<vtkCallbackCommand> Callback;
  vtkNew<TestErrorObserver> Errors;
  EventLog Log;
  Scene(vtkVolumeMapper* mapper, vtkImageData* data)
  {
    PrepareTestWindow(this->Window, 64, 64);
    this->Window->AddRenderer(this->Renderer);
    AddTestLights(this->Renderer);
    PlaceTestCamera(this->Renderer->GetActiveCamera());
    mapper->SetInputData(data);
    this->Volume->SetMapper(mapper);
    this->Volume->SetProperty(MakeTestProperty());
    this->Renderer->AddVolume(this->Volume);
    this->Log.Mapper = mapper;
    this->Callback->SetCallback(Record);
    this->Callback->SetClientData(&this->Log);
    this->Tags = { mapper->AddObserver(vtkCommand::VolumeMapperRenderStartEvent, this->Callback),
      mapper->AddObserver(vtkCommand::VolumeMapperRenderEndEvent, this->Callback),
      mapper->AddObserver(vtkCommand::ErrorEvent, this->Errors),
      mapper->AddObserver(vtkCommand::WarningEvent, this->Errors) };
  }
  ~Scene()
  {
    // The mapper outlives the scene: its observers go with the log they write.
    for (unsigned long tag : this->Tags)
    {
      this->Log.Mapper->RemoveObserver(tag);
    }
    this->Renderer->RemoveAllViewProps();
  }
  std::vector<unsigned long> Tags;
};
} // namespace

int main(int, char*[])
{
  int failures = 0;
  vtkSmartPointer<vtkImageData> data = MakeTestVolume(24);
  vtkNew<vtkImageData> empty; // no scalars: every mapper refuses it
  empty->SetDimensions(4, 4, 4);

  vtkNew<vtkEmissionAbsorptionVolumeMapper> ea;
  vtkNew<vtkAmbientOcclusionVolumeMapper> ao;
  vtkNew<vtkAmbientScatteringVolumeMapper> as;
  vtkNew<vtkGPUVolumeRayCastMapper> vtk;
  vtkVolumeMapper* mappers[] = { ea, ao, as, vtk };
  for (vtkVolumeMapper* mapper : mappers)
  {
    const std::string name = mapper->GetClassName();
    auto* ours = vtkAVSVolumeMapper::SafeDownCast(mapper);
    {
      // Three renders: three pairs, each start before its frame and each end after it.
      Scene scene(mapper, data);
      for (int i = 0; i < 3; ++i)
      {
        // (The first render with its stages timed, the second without.)
        if (ours)
        {
          ours->SetStageTiming(i == 0);
        }
        scene.Window->Render();
        if (ours)
        {
          // Timed: the input, its upload and the frame took time, the precomputed volumes
          // where the mapper has them (ambient scattering's default, the extended model: the
          // averaged extinction, the light volumes and the diffusion; ambient occlusion's
          // volume), and no more than the whole render. Untimed: nothing.
          double sum = 0.0;
          for (int stage = 0; stage < vtkAVSVolumeMapper::NumberOfRenderStages; ++stage)
          {
            sum += ours->GetLastStageSeconds(stage);
          }
          const bool scattering = ours == static_cast<vtkAVSVolumeMapper*>(as);
          auto took = [&](int stage) { return ours->GetLastStageSeconds(stage) > 0.0; };
          if (i == 0)
          {
            std::cout << name << " stages:";
            for (int stage = 0; stage < vtkAVSVolumeMapper::NumberOfRenderStages; ++stage)
            {
              std::cout << " " << vtkAVSVolumeMapper::GetRenderStageName(stage) << " "
                        << ours->GetLastStageSeconds(stage);
            }
            std::cout << "\n";
            AVS_CHECK(took(vtkAVSVolumeMapper::InputStage));
            AVS_CHECK(took(vtkAVSVolumeMapper::UploadStage));
            AVS_CHECK(took(vtkAVSVolumeMapper::FrameStage));
            AVS_CHECK(took(vtkAVSVolumeMapper::AveragedExtinctionStage) == scattering);
            AVS_CHECK(took(vtkAVSVolumeMapper::LightVolumeStage) == (ours != ea.Get()));
            AVS_CHECK(took(vtkAVSVolumeMapper::DiffusionStage) == scattering);
            AVS_CHECK(sum <= ours->GetTimeToDraw());
          }
          else
          {
            AVS_CHECK(sum == 0.0);
          }
        }
      }
      std::cout << name << ": " << scene.Log.Events << "\n";
      AVS_CHECK(scene.Log.Events == "SESESE");
      AVS_CHECK(scene.Errors->Errors == 0);
      if (ours && scene.Log.Frames.size() == 6)
      {
        for (int i = 0; i < 3; ++i)
        {
          AVS_CHECK(scene.Log.Frames[2 * i] == i);         // the start: before the frame
          AVS_CHECK(scene.Log.Frames[2 * i + 1] == i + 1); // the end: after it
        }
      }
      if (ours)
      {
        AVS_CHECK(ours->GetTimeToDraw() > 0.0);
      }
    }
    {
      // A refused render (an image without scalars) fires its pair too, around the error.
      Scene scene(mapper, empty);
      scene.Window->Render();
      std::cout << name << " without scalars: " << scene.Log.Events << ", " << scene.Errors->Errors
                << " error(s)\n";
      AVS_CHECK(scene.Log.Events == "SE");
      if (ours)
      {
        AVS_CHECK(scene.Errors->Errors == 1);
        AVS_CHECK(scene.Log.Frames.size() == 2 && scene.Log.Frames[0] == 3 &&
          scene.Log.Frames[1] == 3); // nothing drawn
      }
    }
  }

  // Our lit mappers refuse a blend mode other than composite: one pair around the error.
  for (vtkAVSVolumeMapper* mapper :
    { static_cast<vtkAVSVolumeMapper*>(ao), static_cast<vtkAVSVolumeMapper*>(as) })
  {
    Scene scene(mapper, data);
    mapper->SetBlendModeToMaximumIntensity();
    const int frames = mapper->GetNumberOfRenderedFrames();
    scene.Window->Render();
    std::cout << mapper->GetClassName() << " maximum intensity: " << scene.Log.Events << "\n";
    AVS_CHECK(scene.Log.Events == "SE");
    AVS_CHECK(scene.Errors->Errors == 1);
    AVS_CHECK(mapper->GetNumberOfRenderedFrames() == frames);
    mapper->SetBlendModeToComposite();
  }

  // Volume peeling (vtkDualDepthPeelingPass with translucent geometry) calls the mapper again
  // within a frame; the volume is drawn once, and the events fire once, per frame.
  for (vtkAVSVolumeMapper* mapper :
    { static_cast<vtkAVSVolumeMapper*>(ea), static_cast<vtkAVSVolumeMapper*>(as) })
  {
    Scene scene(mapper, data);
    vtkNew<vtkSphereSource> ball;
    ball->SetRadius(0.4);
    vtkNew<vtkPolyDataMapper> ballMapper;
    ballMapper->SetInputConnection(ball->GetOutputPort());
    vtkNew<vtkActor> actor;
    actor->SetMapper(ballMapper);
    actor->GetProperty()->SetOpacity(0.5);
    scene.Renderer->AddActor(actor);
    scene.Renderer->SetUseDepthPeeling(1);
    scene.Renderer->SetUseDepthPeelingForVolumes(true);
    scene.Renderer->SetMaximumNumberOfPeels(4);
    const int frames = mapper->GetNumberOfRenderedFrames();
    scene.Window->Render();
    scene.Window->Render();
    std::cout << mapper->GetClassName() << " with volume peeling: " << scene.Log.Events << ", "
              << mapper->GetNumberOfRenderedFrames() - frames << " frames drawn\n";
    AVS_CHECK(scene.Log.Events == "SESE");
    AVS_CHECK(mapper->GetNumberOfRenderedFrames() - frames == 2);
    AVS_CHECK(scene.Errors->Errors == 0);
  }

  std::cout << (failures ? "FAILED" : "passed") << "\n";
  return failures ? 1 : 0;
}

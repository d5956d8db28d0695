#pragma once
/// The stages of the pipeline's results the workstation's 3-D view shows (SceneParts shows them part by part): the
/// organ as the shape model made it; the displaced organ with the grown pathologies; the merged body (one colour per
/// region); the tetrahedral mesh with its tissues (myometrium, endometrium, cervix, each pathology); the textured
/// visual surface. And the growth as it happens.

#include "hs/core/SurfaceMesh.h"
#include "hs/generate/Generate.h"
#include "hs/pathology/Pathology.h"

#include <vtkSmartPointer.h>

#include <map>
#include <optional>
#include <utility>
#include <vector>

class vtkActor;
class vtkPolyData;
class vtkRenderer;

namespace hs::widgets {

enum class ResultLayer { None, Organ, Pathologies, Body, Tissues, Textured };

/// One surface of several, each part's faces labelled "region" with its region id.
SurfaceMesh combineRegions(const std::vector<std::pair<const SurfaceMesh*, int>>& parts);

/// Which layers `results` can show, furthest first is the default choice.
bool hasLayer(const generate::Generated& results, ResultLayer layer);

/// The pathologies' growth as it happens (the frames of pathology::GrowthObserver): the latest points of each
/// pathology as small dots in its region's colour, over whatever the view shows. clear() when the stage has ended.
class GrowthDisplay {
public:
    explicit GrowthDisplay(vtkRenderer* renderer);
    ~GrowthDisplay();
    GrowthDisplay(const GrowthDisplay&) = delete;
    GrowthDisplay& operator=(const GrowthDisplay&) = delete;

    /// Replaces pathology `frame.pathology`'s points by the frame's.
    void show(const pathology::GrowthFrame& frame);
    void clear();
    /// Points shown now, over every pathology.
    std::size_t pointCount() const;

private:
    void rebuild();

    vtkRenderer* m_renderer;
    vtkSmartPointer<vtkActor> m_actor;
    vtkSmartPointer<vtkPolyData> m_points;
    std::map<std::size_t, std::vector<Vec3>> m_latest;
};

} // namespace hs::widgets

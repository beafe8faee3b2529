#pragma once
// Everything one frame needs, as the scene builder hands it over at WorldEnd: frozen options,
// the lights, and every primitive converted to a plain geometric description (shape.h) with its
// attributes and transform. The ray tracer and the photon tracer start from here.

#include <Imath/ImathMatrix.h>

#include <map>
#include <memory>
#include <string>
#include <variant>
#include <vector>

#include "renderer/geometry/shape.h"
#include "renderer/scene/attributes.h"
#include "renderer/scene/lazy_procedurals.h"
#include "renderer/scene/options.h"

namespace gonio {

// A quadric and its primitive variables (constant/uniform: one value, varying/vertex: four, at
// the (u,v) corners (0,0) (1,0) (0,1) (1,1)).
struct QuadricShape {
    std::shared_ptr<const Quadric> quadric;
    PrimVarSet vars;
    // It encloses a volume by itself (a sphere or torus swept all the way round): CSG asks.
    bool closed = false;
};

using ShapeGeometry = std::variant<TriangleMesh, QuadricShape, SubdivisionCage, CurveSet, PointSet>;

struct SceneShape {
    ShapeGeometry geometry;
    std::shared_ptr<const Attributes> attributes;
    // World (or, inside an object definition, definition) space from the shape's object space.
    M44f worldFromObject;
    // Transformation motion blur: world from object at each of these times (empty: static).
    std::vector<float> motionTimes;
    std::vector<M44f> worldFromObjectMotion;
    // Deformation motion blur (meshes and subdivision cages): the positions at each of these
    // times (empty: the geometry does not deform).
    std::vector<float> deformTimes;
    std::vector<std::vector<V3f>> deformPositions;
    // Reverse the outward normal (Orientation "inside", or "lh"/"rh" against the handedness).
    bool flipNormals = false;
    // The "primitive" solid (index into Frame::solids) whose surface this shape is part of;
    // −1 for a shape outside every SolidBegin block.
    int solid = -1;
    // A trimmed NuPatch (TrimCurve): only the points of its mesh whose `uv` lies in the region
    // are surface. Null: untrimmed.
    std::shared_ptr<const TrimRegion> trim;
    FileLoc loc;
};

// A node of a CSG tree (RISpec 3.2 §5.9, SolidBegin/SolidEnd). A "primitive" solid is the
// volume its surfaces (the shapes whose SceneShape::solid names it) enclose, their outward
// normals telling inside from outside; the other operations combine their children. A
// geometric primitive directly inside an operation is a primitive solid of its own.
struct SolidNode {
    enum class Operation { Primitive, Union, Intersection, Difference };
    Operation operation = Operation::Primitive;
    int parent = -1;            // index into Frame::solids; −1 for the root of a tree
    std::vector<int> children;  // in RIB order: a difference takes the later ones from the first
    FileLoc loc;
};

struct ObjectDefinition {
    std::vector<SceneShape> shapes;
    std::shared_ptr<const Attributes> base;  // the attributes current at ObjectBegin
};

struct ObjectInstanceUse {
    std::shared_ptr<const ObjectDefinition> definition;
    M44f worldFromDefinition;
    // The attributes each shape of the definition is shaded with: those current at
    // ObjectInstance, except what the definition itself set (as if its requests were replayed
    // at the instance). One per definition shape.
    std::vector<std::shared_ptr<const Attributes>> shapeAttributes;
    std::vector<float> motionTimes;  // a moving instance: its placement at these times
    std::vector<M44f> worldFromDefinitionMotion;
};

struct SceneLight {
    LightInstance light;
    // Attribute "light" "shadows" "on" when the light was declared: shadows are traced. Off by
    // default, as in BMRT and Aqsis (RenderMan lights cast no shadows unless asked to).
    bool castsShadows = false;
    // An AreaLightSource's geometry (RISpec 3.2 §4.1.3): indices into Frame::shapes of the
    // primitives that follow it in the same attribute block, which are also ordinary visible
    // geometry. Polygons, patches, NURBS, quadrics and subdivision meshes join it; curves,
    // points and shapes inside object definitions (and so their instances) do not, each with a
    // warning. Empty for a LightSource, and for an area light with no geometry (it lights
    // from the origin of its shader space, as a LightSource would).
    std::vector<size_t> shapes;
    // Attribute "light" "nsamples" when the light was declared: the points on an area light's
    // surface its shader runs at for each shaded point (stratified; at least 1).
    int samples = 16;
};

struct Frame {
    int number = 0;   // FrameBegin's
    int ordinal = 0;  // the count of WorldBegin before this frame's
    Options options;
    std::vector<SceneLight> lights;
    std::vector<SceneShape> shapes;
    std::vector<ObjectInstanceUse> instances;
    std::vector<SolidNode> solids;  // every CSG tree's nodes, parents before their children
    // CoordinateSystem names: world space from the named space.
    std::map<std::string, M44f> namedSpaces;
    std::string sceneFile;  // the RIB file, for resolving relative output and search paths
    // The DelayedReadArchives outside the view, not read; rays mark those they reach.
    LazyProcedurals lazyProcedurals;
};

}  // namespace gonio

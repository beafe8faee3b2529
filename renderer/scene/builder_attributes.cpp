// SceneBuilder: the attributes of RISpec §4.2 and the transformations of §4.3.

#include <Imath/ImathMatrixAlgo.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "base/math.h"
#include "renderer/scene/scene_builder_state.h"
#include "renderer/scene/scene_colors.h"
#include "renderer/scene/standard_options.h"
#include "renderer/scene/view_frustum.h"

namespace gonio {
namespace {

constexpr float kDegrees = kPiF / 180.f;

std::string HandleKey(const RtHandle& handle) {
    return (handle.isString ? "s:" : "i:") + handle.text;
}

bool LightCastsShadows(const Attributes& attributes) {
    auto it = attributes.user.find("light");
    return it != attributes.user.end() && it->second.GetString("shadows", "off") == "on";
}

int LightSamples(const Attributes& attributes) {
    auto it = attributes.user.find("light");
    if (it == attributes.user.end()) return SceneLight().samples;
    return std::max(1, int(it->second.GetFloat("nsamples", float(SceneLight().samples))));
}

}  // namespace

int SceneBuilder::MotionSampleIndex() {
    return state_->motionRequestCount < 0 ? -1 : state_->motionRequestCount++;
}

// ---- colour and shaders ---------------------------------------------------------------------

void SceneBuilder::Color(const std::vector<float>& color, const FileLoc& loc) {
    std::vector<float> components;
    std::string error;
    if (!SceneColorsFromNumbers(state_->options, color, 1, &components, &error)) {
        diagnostics_.Error(loc, "Color: " + error);
        return;
    }
    MutableAttributes().color = components;
}

void SceneBuilder::Opacity(const std::vector<float>& opacity, const FileLoc& loc) {
    std::vector<float> components;
    std::string error;
    if (!SceneColorsFromNumbers(state_->options, opacity, 1, &components, &error)) {
        diagnostics_.Error(loc, "Opacity: " + error);
        return;
    }
    MutableAttributes().opacity = components;
}

void SceneBuilder::TextureCoordinates(const std::vector<float>& st8, const FileLoc& loc) {
    if (st8.size() != 8) {
        diagnostics_.Error(loc, "TextureCoordinates needs 8 numbers");
        return;
    }
    MutableAttributes().textureCoordinates = st8;
}

// Under Option "spectral", a colour parameter may be RGB or name one spectrum
// (scene_colors.h); its count then differs from the frame's components.
bool SceneBuilder::IsSpectralColor(const Param& param) const {
    if (state_->options.wavelengths.empty() && !state_->options.spectraAsRgb) return false;
    std::string unused;
    const std::optional<ParamDecl> decl = declarations_.Resolve(param.token, &unused);
    if (!decl || decl->type != ParamType::Color) return false;
    return param.isString ? param.strings.size() == 1 : param.numbers.size() % 3 == 0;
}

void SceneBuilder::SetShader(ShaderInstance* shader, const std::string& name,
                             const ParamList& params, const FileLoc& loc) {
    for (const Param& p : params) {  // typed here so that undeclared tokens are reported early
        if (IsSpectralColor(p)) continue;  // RGB or a spectrum: the shading stage converts it
        PrimVar var;
        TypeParam(p, declarations_, state_->options.colorComponents, diagnostics_, &var);
    }
    shader->name = name;
    shader->params = params;
    shader->worldFromShader = state_->transform;
    shader->loc = loc;
}

void SceneBuilder::LightSource(const std::string& name, const RtHandle& handle,
                               const ParamList& params, const FileLoc& loc) {
    SceneLight light;
    SetShader(&light.light.shader, name, params, loc);
    light.light.handle = handle;
    light.castsShadows = LightCastsShadows(state_->attributes);
    light.samples = LightSamples(state_->attributes);
    if (state_->inWorld)
        AddLight(std::move(light));
    else
        state_->cameraLights.push_back(std::move(light));
}

void SceneBuilder::AddLight(SceneLight light) {
    const int index = static_cast<int>(state_->frame.lights.size());
    ApplyPlannedLightColor(index, &light.light);
    state_->lightHandles[HandleKey(light.light.handle)] = index;
    state_->frame.lights.push_back(std::move(light));
    MutableAttributes().activeLights.insert(index);
}

// The primitives that follow in this attribute block are the light's geometry (AddShape);
// before WorldBegin there is no geometry to give it, and it lights from its origin.
void SceneBuilder::AreaLightSource(const std::string& name, const RtHandle& handle,
                                   const ParamList& params, const FileLoc& loc) {
    LightSource(name, handle, params, loc);
    auto& lights = state_->inWorld ? state_->frame.lights : state_->cameraLights;
    lights.back().light.isArea = true;
    if (state_->inWorld)
        MutableAttributes().areaLight = int(lights.size()) - 1;
    else
        diagnostics_.WarningOnce("AreaLightSource outside world", loc,
                                 "AreaLightSource before WorldBegin has no geometry and lights "
                                 "from its origin, as a LightSource would");
}

int SceneBuilder::LightIndex(const RtHandle& handle, const FileLoc& loc) {
    auto it = state_->lightHandles.find(HandleKey(handle));
    if (it != state_->lightHandles.end()) return it->second;
    diagnostics_.Error(loc, "Illuminate: no light has handle " +
                                (handle.isString ? "\"" + handle.text + "\"" : handle.text));
    return -1;
}

void SceneBuilder::Illuminate(const RtHandle& light, bool on, const FileLoc& loc) {
    if (!RequireWorld("Illuminate", loc)) return;
    const int index = LightIndex(light, loc);
    if (index < 0) return;
    if (on)
        MutableAttributes().activeLights.insert(index);
    else
        MutableAttributes().activeLights.erase(index);
}

void SceneBuilder::Surface(const std::string& name, const ParamList& params, const FileLoc& loc) {
    SetShader(&MutableAttributes().surface, name, params, loc);
}

void SceneBuilder::Displacement(const std::string& name, const ParamList& params,
                                const FileLoc& loc) {
    SetShader(&MutableAttributes().displacement, name, params, loc);
}

void SceneBuilder::Atmosphere(const std::string& name, const ParamList& params,
                              const FileLoc& loc) {
    SetShader(&MutableAttributes().atmosphere, name, params, loc);
}

void SceneBuilder::Interior(const std::string& name, const ParamList& params, const FileLoc& loc) {
    SetShader(&MutableAttributes().interior, name, params, loc);
}

void SceneBuilder::Exterior(const std::string& name, const ParamList& params, const FileLoc& loc) {
    SetShader(&MutableAttributes().exterior, name, params, loc);
}

void SceneBuilder::ShadingRate(float size, const FileLoc& loc) {
    if (!(size > 0) || !std::isfinite(size)) {
        diagnostics_.Error(loc, "ShadingRate must be a positive, finite area in pixels");
        return;
    }
    MutableAttributes().shadingRate = size;
}

// ---- REYES-only attributes: accepted, ignored with one note each ------------------------------

void SceneBuilder::ShadingInterpolation(const std::string&, const FileLoc& loc) {
    IgnoredRequest("ShadingInterpolation", loc);
}
void SceneBuilder::Bound(const std::vector<float>&, const FileLoc& loc) {
    IgnoredRequest("Bound", loc);
}
// ---- level of detail ------------------------------------------------------------------------

bool ShownAtDetail(float detail, const float range[4]) {
    const float minVisible = range[0], lower = range[1], upper = range[2], maxVisible = range[3];
    if (!(detail >= minVisible && detail <= maxVisible)) return false;
    if (detail < lower) return detail - minVisible > 0.5f * (lower - minVisible);
    if (detail > upper) return maxVisible - detail >= 0.5f * (maxVisible - upper);
    return true;
}

void SceneBuilder::Detail(const std::vector<float>& bound, const FileLoc& loc) {
    if (bound.size() != 6) {
        diagnostics_.Error(loc, "Detail expects 6 numbers (xmin xmax ymin ymax zmin zmax), got " +
                                    std::to_string(bound.size()));
        return;
    }
    // Inside an object definition the camera is not where the instances will be: the detail
    // stays infinite there (the finest representation), as it does outside the world.
    float detail = std::numeric_limits<float>::infinity();
    const Options& options = state_->options;
    if (state_->inWorld && !state_->openObject)
        detail = BoxDetail(options, state_->transform * options.cameraFromWorld, bound.data());
    MutableAttributes().detail = detail * options.relativeDetail;
}

void SceneBuilder::DetailRange(float minVisible, float lowerTransition, float upperTransition,
                               float maxVisible, const FileLoc& loc) {
    if (!(minVisible <= lowerTransition && lowerTransition <= upperTransition &&
          upperTransition <= maxVisible)) {
        diagnostics_.Error(loc,
                           "DetailRange expects minvisible <= lowertransition <= "
                           "uppertransition <= maxvisible");
        return;
    }
    float* range = MutableAttributes().detailRange;
    range[0] = minVisible, range[1] = lowerTransition, range[2] = upperTransition,
    range[3] = maxVisible;
}
void SceneBuilder::GeometricApproximation(const std::string&, float, const FileLoc& loc) {
    IgnoredRequest("GeometricApproximation", loc);
}

void SceneBuilder::Matte(bool on, const FileLoc&) { MutableAttributes().matte = on; }

// ---- orientation ----------------------------------------------------------------------------

void SceneBuilder::Orientation(const std::string& orientation, const FileLoc& loc) {
    using O = Attributes::Orientation;
    static const std::pair<const char*, O> kNames[] = {{"outside", O::Outside},
                                                       {"inside", O::Inside},
                                                       {"lh", O::LeftHanded},
                                                       {"rh", O::RightHanded}};
    for (const auto& [name, value] : kNames) {
        if (orientation == name) {
            MutableAttributes().orientation = value;
            return;
        }
    }
    diagnostics_.Error(
        loc, "Orientation must be outside, inside, lh or rh, got \"" + orientation + "\"");
}

void SceneBuilder::ReverseOrientation(const FileLoc&) {
    using O = Attributes::Orientation;
    static const O kReversed[] = {O::Inside, O::Outside, O::RightHanded, O::LeftHanded};
    MutableAttributes().orientation = kReversed[static_cast<int>(state_->attributes.orientation)];
}

void SceneBuilder::Sides(int sides, const FileLoc& loc) {
    if (sides != 1 && sides != 2) {
        diagnostics_.Error(loc, "Sides must be 1 or 2, got " + std::to_string(sides));
        return;
    }
    MutableAttributes().twoSided = sides == 2;
}

void SceneBuilder::Attribute(const std::string& name, const ParamList& params, const FileLoc& loc) {
    if (!IsKnownOptionName(false, name))
        diagnostics_.WarningOnce("Attribute " + name, loc,
                                 "unknown Attribute \"" + name + "\" (kept for shaders)");
    ParamDict& merged = MutableAttributes().user[name];
    for (const Param& p : params) {
        TypedParam typed;
        if (TypeOptionParam("Attribute", name, p, &typed)) merged.Set(std::move(typed), p.loc);
    }
    if (name == "identifier") MutableAttributes().identifier = merged.GetString("name", "");
    if (name == "spectral") SpectralAttribute(merged);
    if (name == "visibility") CheckTransmission(merged, loc);
}

// The words shadow_transmission.h knows; another is a warning and means "Os".
void SceneBuilder::CheckTransmission(const ParamDict& visibility, const FileLoc& loc) {
    if (!visibility.Has("transmission")) return;
    const std::string mode = visibility.GetString("transmission", "");
    for (const char* known : {"opaque", "transparent", "Os", "shader"})
        if (mode == known) return;
    diagnostics_.Warning(loc,
                         "Attribute \"visibility\" \"transmission\" must be opaque, "
                         "transparent, Os or shader, got \"" +
                             mode + "\" (taken as Os)");
}

// Attribute "spectral" "string color" NAME | "string opacity" NAME: Color or Opacity as a named
// spectrum or a spectrum file, at the frame's wavelengths (Option "spectral").
void SceneBuilder::SpectralAttribute(const ParamDict& params) {
    for (const char* which : {"color", "opacity"}) {
        if (!params.Has(which)) continue;
        std::vector<float> components;
        std::string error;
        if (!SceneColorFromSpectrum(state_->options, params.GetString(which, ""), &components,
                                    &error)) {
            diagnostics_.Error(params.Location(which), "Attribute \"spectral\": " + error);
            continue;
        }
        (std::string(which) == "color" ? MutableAttributes().color : MutableAttributes().opacity) =
            components;
    }
}

void SceneBuilder::Basis(const RtBasis& ubasis, int ustep, const RtBasis& vbasis, int vstep,
                         const FileLoc& loc) {
    auto resolve = [&](const RtBasis& basis, int step, PatchBasis* out) {
        if (basis.name.empty()) {
            out->matrix = ToM44f(basis.matrix);
        } else if (std::optional<PatchBasis> named = NamedBasis(basis.name)) {
            out->matrix = named->matrix;
        } else {
            diagnostics_.Error(loc, "Basis: unknown basis \"" + basis.name + "\"");
            return;
        }
        out->step = step;
    };
    resolve(ubasis, ustep, &MutableAttributes().ubasis);
    resolve(vbasis, vstep, &MutableAttributes().vbasis);
}

// RISpec §5.2: the trim curves are an attribute, applied to the NuPatches that follow.
void SceneBuilder::TrimCurve(const std::vector<int>& ncurves, const std::vector<int>& order,
                             const std::vector<float>& knot, const std::vector<float>& min,
                             const std::vector<float>& max, const std::vector<int>& n,
                             const std::vector<float>& u, const std::vector<float>& v,
                             const std::vector<float>& w, const FileLoc& loc) {
    GeometryResult<TrimRegion> region = MakeTrimRegion(ncurves, order, knot, min, max, n, u, v, w);
    if (!region) {
        diagnostics_.Error(loc, region.Error());
        return;
    }
    MutableAttributes().trimCurves = std::make_shared<const TrimRegion>(region.Take());
}

// ---- transformations ------------------------------------------------------------------------
// RIB uses row vectors (p' = p·M), as Imath does: a new transform applies to object points
// first, so it multiplies from the left.

void SceneBuilder::ChangeTransform(const M44f& m, bool concatenate) {
    auto apply = [&](const M44f& base) { return concatenate ? m * base : m; };
    const int k = MotionSampleIndex();
    if (k < 0) {
        state_->transform = apply(state_->transform);
        for (M44f& sample : state_->transformSamples) sample = apply(sample);
        return;
    }
    const std::vector<M44f>& base = state_->motionBase;
    if (k >= int(base.size())) return;  // more requests than times: the extra ones are ignored
    if (k == 0) {
        // Until the block's later requests arrive, every time sees the first one.
        state_->transformTimes = state_->motionTimes;
        state_->transformSamples.clear();
        for (const M44f& b : base) state_->transformSamples.push_back(apply(b));
        state_->transform = state_->transformSamples[0];
        return;
    }
    for (size_t i = k; i < base.size(); ++i) state_->transformSamples[i] = apply(base[i]);
}

void SceneBuilder::ConcatTransform(const M44f& m) { ChangeTransform(m, true); }

void SceneBuilder::Identity(const FileLoc&) { ChangeTransform(M44f(), false); }

void SceneBuilder::Transform(const RtMatrix& m, const FileLoc&) {
    ChangeTransform(ToM44f(m), false);
}

void SceneBuilder::ConcatTransform(const RtMatrix& m, const FileLoc&) {
    ConcatTransform(ToM44f(m));
}

void SceneBuilder::Perspective(float fov, const FileLoc& loc) {
    if (!(fov > 0 && fov < 180)) {
        diagnostics_.Error(loc, "Perspective needs 0 < fov < 180");
        return;
    }
    // A projective matrix cannot be part of a ray tracer's camera transform: treat it as the
    // Projection it almost always stands for.
    diagnostics_.NoteOnce("Perspective", loc,
                          "Perspective is rendered as Projection \"perspective\" with this fov");
    state_->options.projection = "perspective";
    state_->options.fov = fov;
}

void SceneBuilder::Translate(float dx, float dy, float dz, const FileLoc&) {
    M44f m;
    m.setTranslation(Imath::V3f(dx, dy, dz));
    ConcatTransform(m);
}

void SceneBuilder::Rotate(float angle, float dx, float dy, float dz, const FileLoc& loc) {
    Imath::V3f axis(dx, dy, dz);
    if (axis.length() == 0) {
        diagnostics_.Error(loc, "Rotate: the axis is zero");
        return;
    }
    M44f m;
    m.setAxisAngle(axis.normalized(), angle * kDegrees);
    ConcatTransform(m);
}

void SceneBuilder::Scale(float sx, float sy, float sz, const FileLoc&) {
    M44f m;
    m.setScale(Imath::V3f(sx, sy, sz));
    ConcatTransform(m);
}

// RISpec §4.3 RiSkew: shifts points along d2 so that the vector d1 turns by `angle` towards d2
// (all three in one plane). With p̂ the unit part of d1 perpendicular to d2 and θ the angle from
// d2 to d1, the shear p' = p + k (p·p̂) d̂2 takes cot θ to cot θ + k, so k = cot(θ − angle) − cot θ.
void SceneBuilder::Skew(float angle, float dx1, float dy1, float dz1, float dx2, float dy2,
                        float dz2, const FileLoc& loc) {
    Imath::V3f d1(dx1, dy1, dz1), d2(dx2, dy2, dz2);
    if (d1.length() == 0 || d2.length() == 0) {
        diagnostics_.Error(loc, "Skew: a direction is zero");
        return;
    }
    d1.normalize();
    d2.normalize();
    const float cosTheta = d1.dot(d2);
    const Imath::V3f perp = d1 - cosTheta * d2;
    const float theta = std::acos(std::fmax(-1.f, std::fmin(1.f, cosTheta)));
    const float target = theta - angle * kDegrees;
    if (perp.length() == 0 || target <= 0 || target >= kPiF) {
        diagnostics_.Error(loc, "Skew: the angle is out of range for these directions");
        return;
    }
    const Imath::V3f p = perp / perp.length();
    const float k = std::cos(target) / std::sin(target) - std::cos(theta) / std::sin(theta);
    M44f m;  // rows are the images of the basis vectors
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) m[r][c] += k * p[r] * d2[c];
    ConcatTransform(m);
}

void SceneBuilder::CoordinateSystem(const std::string& space, const FileLoc&) {
    auto& spaces = state_->inWorld ? state_->frame.namedSpaces : state_->namedSpaces;
    spaces[space] = state_->transform;
}

void SceneBuilder::ScopedCoordinateSystem(const std::string& space, const FileLoc& loc) {
    CoordinateSystem(space, loc);
}

void SceneBuilder::CoordSysTransform(const std::string& space, const FileLoc& loc) {
    if (space == "world" && state_->inWorld) {
        ChangeTransform(M44f(), false);
        return;
    }
    const auto& spaces = state_->inWorld ? state_->frame.namedSpaces : state_->namedSpaces;
    auto it = spaces.find(space);
    if (it == spaces.end()) {
        diagnostics_.Error(loc, "CoordSysTransform: no coordinate system named \"" + space + "\"");
        return;
    }
    ChangeTransform(it->second, false);
}

}  // namespace gonio

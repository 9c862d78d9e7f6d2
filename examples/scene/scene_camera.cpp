#include "examples/scene/scene_camera.h"

#include <cmath>

namespace opal::scene {
namespace {

using namespace usda::types;

// UsdGeomCamera's fallbacks (a 35 mm film back in tenths of a scene unit).
constexpr double FocalLengthFallback = 50.0;
constexpr double HorizontalApertureFallback = 20.955;
constexpr double VerticalApertureFallback = 15.2908;
constexpr double NearFallback = 1.0, FarFallback = 1000000.0;

void readClippingRange(PrimReader& reader, hd::CameraDesc& desc) {
    desc.nearClip = NearFallback;
    desc.farClip = FarFallback;
    const usda::Attribute* range = reader.find("clippingRange", {Float2});
    if (!range) return;
    const usda::Vec2f& r = std::get<usda::Vec2f>(range->value->data());
    if (!(r[0] > 0.0f && r[1] > r[0] && std::isfinite(r[1])))
        reader.failAt(*range, "is (" + formatNumber(r[0]) + ", " + formatNumber(r[1]) +
                                  "), expected (near, far) with 0 < near < far");
    desc.nearClip = r[0];
    desc.farClip = r[1];
}

void rejectUnsupported(PrimReader& reader) {
    reader.requireFallback<Token>("projection", "perspective", "orthographic cameras are not implemented");
    reader.requireFallback<Float>("horizontalApertureOffset", 0.0f, "aperture offsets are not implemented");
    reader.requireFallback<Float>("verticalApertureOffset", 0.0f, "aperture offsets are not implemented");
    reader.requireFallback<Float>("fStop", 0.0f, "depth of field is not implemented");
    reader.requireFallback<Float>("exposure", 0.0f, "use the lights' inputs:exposure");
    reader.requireFallback<Token>("stereoRole", "mono", "stereo cameras are not implemented");
    reader.requireFallback<Float4Array>("clippingPlanes", {}, "extra clipping planes are not implemented");
    reader.ignore("focusDistance");   // only used with an fStop
    reader.ignore("shutter:open");    // a static scene has no motion blur
    reader.ignore("shutter:close");
}

}  // namespace

hd::CameraDesc readCamera(PrimReader& reader, const Imath::M44d& objectToWorld) {
    hd::CameraDesc desc;
    desc.transform = objectToWorld;
    desc.focalLength = reader.real("focalLength", Float, Bounds::positive()).value_or(FocalLengthFallback);
    desc.horizontalAperture =
        reader.real("horizontalAperture", Float, Bounds::positive()).value_or(HorizontalApertureFallback);
    desc.verticalAperture = reader.real("verticalAperture", Float, Bounds::positive()).value_or(VerticalApertureFallback);
    readClippingRange(reader, desc);
    rejectUnsupported(reader);
    return desc;
}

}  // namespace opal::scene

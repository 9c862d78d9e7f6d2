// opal-view --script FILE: one action per line, read and checked before anything runs, so a
// misspelt action fails at once with FILE:LINE. Blank lines and '#' comments are skipped;
// words are separated by spaces, and a word with spaces is written in double quotes.
//
//   load PATH                          open a scene or asset layer
//   material set sigma_s|sigma_a R G B the selected mesh's material, mm^-1 per channel
//   material set eta|roughness V
//   material set albedo R G B          the total diffuse reflectance per channel (0 to 1),
//                                      the mean free path kept (sigma_s', sigma_a converted)
//   material set mfp R G B             the diffuse mean free path per channel (mm), the
//                                      albedo kept
//   material reset                     back to the asset's baked default
//   material preset NAME               a measured material (marble, skin1, ...), eta included
//   light move PATH X Y Z              a light's position in world space
//   light turn PATH DX DY              a distant light turned as a left drag of DX, DY pixels
//                                      (y down) in the viewport turns it (light_drag.h)
//   light set PATH intensity|exposure V
//   light set PATH color R G B
//   light set PATH temperature K|off   UsdLux colour temperature (kelvin, 500 to 40000) times
//                                      the color, or off
//   light set PATH radius R            a sphere or spot light's radius (scene units)
//   light set PATH cone DEGREES        a sphere light's cone (0 to 180 off its axis): a spot
//   light set PATH softness S          a spot light's cone softness, 0 to 1
//   light set PATH angle DEGREES       a distant light's angular diameter, 0 to 180
//   light set PATH flicker AMPLITUDE HZ SEED   a shadow-field light's flicker (amplitude 0
//                                      to 1, 0: steady; 0 to 1000 Hz; a whole seed)
//   light add point|sphere|spot|distant|dome [PATH]
//                                      a new light (default: under /_OpalView/Lights), selected
//   light add shadowfield LAYER.usda [PATH]  a baked light layer (opal-bake light) as a new
//                                      light where a new point light would go
//   light remove PATH
//   light rename PATH NAME             a new last element of its path
//   light enable|disable PATH          a disabled light stays in the scene, unlit
//   environment rotate DEGREES         turns the dome (the first DomeLight) about +Y
//   environment texture FILE           a lat-long image for the dome
//   environment background on|off      whether the camera sees the dome behind the asset
//   undo | redo                        material and light edits
//   setting KEY VALUE                  a render setting of the delegate (opal:reference true,
//                                      opal:samplesPerPixel 4, ...), typed by its descriptor
//   view DISPLAY VIEW                  the OCIO display and view
//   exposure STOPS                     display exposure
//   gamma G                            display gamma: the shown values to the power 1 / G
//   aov NAME                           the AOV shown (hd/aov.h), one the delegate renders
//   delegate TYPE                      render with another renderer plugin the registry found
//                                      (OpalPreviewRendererPlugin, ...): same scene, camera, edits
//   delegates                          prints the delegate picker's list: every renderer plugin
//                                      found ("* " marks the one in use) and what was skipped
//   wipe on|off|X                      the A/B wipe: the engine left of a vertical line, the
//                                      exact reference (opal:reference) right of it; X puts
//                                      the line at that fraction of the width (0 to 1)
//   panel help|stats|settings|probe|delegates on|off   the optional panels (the View menu)
//   gizmos on|off                      the light gizmos over the picture (View > Light gizmos)
//   camera frame|reset                 frame everything; back to the camera the file opened with
//   camera frame selection             frame the selected mesh
//   camera use PATH|free               look through one of the scene's cameras (it follows
//                                      scene time), or the free camera from where it looks
//   camera orbit YAW PITCH             degrees, added to the free camera's
//   camera focal MM                    the free camera's focal length (film 36 x 24 mm unless
//                                      the scene's camera says otherwise), 1 to 10000
//   camera fov DEGREES                 the free camera's horizontal field of view, 1 to 170
//                                      (the focal length that gives it in this window)
//   camera clip NEAR FAR|auto          the free camera's clipping planes, or automatic ones
//                                      holding the whole scene
//   select PATH                        a mesh (the material panel edits it, frame selection
//                                      frames it) or a light (the viewport drags it)
//   time CODE                          scene time (the layer's time codes), paused there
//   play | pause                       scene time runs with the wall clock, or stops
//   wait [SECONDS]                     until the picture converged (default 300 s)
//   drag material SECONDS              a person dragging the sigma_a green slider back and
//                                      forth (2 s a sweep), then letting go; prints what the
//                                      interface showed meanwhile (edit_latency.h)
//   drag light PATH SECONDS            the same, circling the light about the object (4 s a turn;
//                                      a distant light turns so)
//   screenshot OUT.png                 the window's pixels, interface included
//   save exr OUT.exr                   every AOV, scene-linear (waits for convergence)
//   save png OUT.png                   the AOV shown, display-referred, the color AOV with its
//                                      alpha (waits for convergence)
//   save usda OUT.usda                 the edited scene through the current camera at the
//                                      window's size, for opal-render (usda_export.h)
//   probe X Y                          prints every AOV's scene-linear value at pixel (X, Y)
//                                      (from the top left) and the shown display value
//   quit
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace opal::view {

enum class ActionKind {
    Load, MaterialSet, MaterialReset, MaterialPreset, LightMove, LightTurn, LightSet, LightAdd, LightRemove, LightRename,
    LightEnable, Environment, Undo, Redo, Setting, Panel, Gizmos, View, Exposure, Gamma, Aov, Delegate, Delegates, CameraFrame, CameraReset, CameraOrbit, CameraFocal, CameraUse, CameraFov, CameraClip, Select, Wipe, Time, Play, Wait, Drag, Screenshot,
    SaveExr, SavePng, SaveUsda, Probe, Quit
};

struct ScriptAction {
    ActionKind kind = ActionKind::Quit;
    std::string where;                // "FILE:LINE", the prefix of every message about it
    std::vector<std::string> words;   // paths, names and parameter names, in order
    std::vector<double> numbers;      // the numeric arguments, in order
};

// Throws opal::Error "FILE:LINE: ..." at the first line that is not an action above.
std::vector<ScriptAction> parseScript(const std::string& text, const std::string& fileName);
// Reads the file first (an unreadable file is an error naming it).
std::vector<ScriptAction> readScript(const std::filesystem::path& file);

}  // namespace opal::view

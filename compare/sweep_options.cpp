// The options of `triptych sweep`: lists where the sweep varies a setting, single values
// where it does not. Each help text says what the option does, which pipelines read it
// and its default.
#include "compare/sweep.h"

namespace tp::cli {

void addSweepOptions(CLI::App& cmd, SweepOptions& o) {
    cmd.add_option("scene", o.scene.scene,
                   "Scene: a glTF 2.0 file (.gltf/.glb) or builtin:NAME (courtyard, courtyard-small). "
                   "Default: the built-in courtyard");
    cmd.add_option("--lights", o.lights,
                   "Comma-separated counts of generated lights (added to the scene's own); one uploaded scene "
                   "per count")
        ->capture_default_str();
    cmd.add_option("--res", o.res, "Comma-separated output resolutions WIDTHxHEIGHT")->capture_default_str();
    cmd.add_option("--msaa", o.msaa, "Comma-separated samples per pixel (1, 2, 4, 8 as the device supports)")
        ->capture_default_str();
    cmd.add_option("--tile", o.tile, "Comma-separated tile edges in pixels (8, 16, 32); read by forwardplus and deferred")
        ->capture_default_str();
    cmd.add_option("--light-lists", o.lightLists,
                   "Comma-separated Forward+ light-list layouts (compact, fixed, linked); read by forwardplus")
        ->capture_default_str();
    cmd.add_option("--tile-capacity", o.tileCapacity, "Light slots per tile of the 'fixed' layout (one value)")
        ->check(CLI::Range(1u, 65536u))
        ->capture_default_str();
    cmd.add_option("--gbuffer", o.gbuffer, "Comma-separated G-buffer layouts (compact, wide); read by deferred")
        ->capture_default_str();
    cmd.add_option("--gbuffer-msaa", o.gbufferMsaa,
                   "Comma-separated deferred G-buffer rates under MSAA (pixel: material once per pixel, edges lit "
                   "per sample; sample: material evaluated and lit at every sample); read by deferred")
        ->capture_default_str();
    cmd.add_option("--deferred-lighting", o.deferredLighting,
                   "Comma-separated deferred lighting modes (tiled: compute with per-tile lists; volumes: one "
                   "draw per light); read by deferred")
        ->capture_default_str();
    cmd.add_option("--accum", o.accum,
                   "Comma-separated accumulation precisions (fp16, fp32); read by multipass_forward")
        ->capture_default_str();
    cmd.add_option("--pipelines", o.pipelines,
                   "Comma-separated pipelines to run (default: every registered one); the reference runs anyway "
                   "unless --reference-frames 0");
    cmd.add_option("--frames", o.frames, "Timed frames per pipeline run (median/min/max are over these)")
        ->capture_default_str();
    cmd.add_option("--warmup", o.warmup, "Untimed warm-up frames before each pipeline run's timed ones")
        ->capture_default_str();
    cmd.add_option("--reference-frames", o.referenceFrames,
                   "Timed frames of the reference, with no warm-up: it is rendered for its image, once per light "
                   "count, resolution and MSAA. 0: no reference, no error figures")
        ->check(CLI::Range(0, 1000))
        ->capture_default_str();
    cmd.add_option("--reference-precision", o.referencePrecision,
                   "Light-sum accumulation of the reference (fp64 needs shaderFloat64)")
        ->check(CLI::IsMember({"fp32", "fp64"}))
        ->capture_default_str();
    addReferenceMsaaOption(cmd, o.referenceMsaa);
    addSeedOption(cmd, o.scene.seed);
    cmd.add_option("--light-types", o.scene.lightTypes,
                   "Generated light type mix: point, spot, directional with optional weights, e.g. point:3,spot:1")
        ->capture_default_str();
    cmd.add_option("--light-radius", o.scene.lightRadius,
                   "MIN,MAX light range in scene units (default: 4%-12% of the scene's diagonal)");
    cmd.add_option("--light-intensity", o.scene.lightIntensity,
                   "MIN,MAX intensity in candela (default: derived from the radius)");
    cmd.add_flag("--no-scene-lights", o.scene.dropSceneLights, "Ignore lights defined in the glTF file");
    cmd.add_option("--out", o.out,
                   "Output directory (created if missing) for sweep.csv, sweep.json and sweep.html")
        ->capture_default_str();
    addDeviceOptions(cmd, o.device);
}

} // namespace tp::cli

#pragma once
// The viewer's ImGui panels (ui_panels.cpp: controls; ui_numbers.cpp: numbers, inspector,
// export). Every pipeline control comes from the registry and the knob schema.
namespace tp::view {

class ViewerApp;

struct Panels {
    static void pipelines(ViewerApp& app);
    static void knobs(ViewerApp& app);
    static void view(ViewerApp& app);
    static void lights(ViewerApp& app);
    static void scene(ViewerApp& app);
    static void camera(ViewerApp& app);
    static void numbers(ViewerApp& app);
    static void inspector(ViewerApp& app);
    static void exporting(ViewerApp& app);
    static void status(ViewerApp& app);
};

} // namespace tp::view

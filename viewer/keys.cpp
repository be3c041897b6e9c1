#include "viewer/keys.h"

#include "viewer/viewer_app.h"

namespace tp::view {

bool isHeldKey(int key) {
    return key == 'W' || key == 'A' || key == 'S' || key == 'D' || key == 'Q' || key == 'E';
}

bool applyKey(ViewerApp& app, int key) {
    switch (key) {
    case 'F':
        app.toggleFlip();
        return true;
    case 'R':
        app.requestReference();
        return true;
    case ' ': // GLFW_KEY_SPACE
        app.togglePlay();
        return true;
    case 'W':
        app.moveCamera(1, 0, 0);
        return true;
    case 'S':
        app.moveCamera(-1, 0, 0);
        return true;
    case 'A':
        app.moveCamera(0, -1, 0);
        return true;
    case 'D':
        app.moveCamera(0, 1, 0);
        return true;
    case 'E':
        app.moveCamera(0, 0, 1);
        return true;
    case 'Q':
        app.moveCamera(0, 0, -1);
        return true;
    case '1':
        app.state().mode = DisplayMode::Split;
        return true;
    case '2':
        app.state().mode = DisplayMode::Difference;
        return true;
    case '3':
        app.state().mode = DisplayMode::Overlay;
        return true;
    default:
        return false;
    }
}

} // namespace tp::view

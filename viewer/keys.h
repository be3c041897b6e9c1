#pragma once
// The viewer's keys, one table for the window (GLFW key codes of letters are their ASCII
// upper case) and for scripts (`key F`): F flips A and B, W/A/S/D/Q/E fly, R renders the
// reference now, 1/2/3 pick split / difference / overlay, Space plays or pauses the path.
namespace tp::view {

class ViewerApp;

// True when `key` is one of the viewer's keys (it was applied).
bool applyKey(ViewerApp& app, int key);
// Keys held down move the camera every frame (fly), not once per press.
bool isHeldKey(int key);

} // namespace tp::view

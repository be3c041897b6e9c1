#include "viewer/path_player.h"

namespace tp::view {

bool PathPlayer::advance() {
    if (!loaded()) return playing = false;
    if (frame + 1 < frames) {
        ++frame;
        return true;
    }
    if (loop && frames > 1) {
        frame = 0;
        return true;
    }
    return playing = false;
}

} // namespace tp::view

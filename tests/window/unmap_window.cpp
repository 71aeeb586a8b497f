// Unmaps a window for a while, as a window manager does when the user minimises it (the window test
// of a hidden lesson window: it must wait for events instead of rendering frames nobody sees).
//   fx_unmap_window <title prefix> <seconds hidden>
// Waits up to 20 s for a top-level window whose name starts with the prefix and until it is mapped,
// unmaps it, sleeps, maps it again. Exits 1 when no such window appears.
#include <X11/Xlib.h>
#include <X11/Xutil.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <thread>

namespace {

Window findWindow(Display* display, Window root, const std::string& prefix) {
    Window parent = 0, rootReturn = 0, *children = nullptr;
    unsigned int count = 0;
    if (!XQueryTree(display, root, &rootReturn, &parent, &children, &count)) return 0;
    Window found = 0;
    for (unsigned int i = 0; i < count && !found; ++i) {
        char* name = nullptr;
        if (XFetchName(display, children[i], &name) && name) {
            if (std::strncmp(name, prefix.c_str(), prefix.size()) == 0) found = children[i];
            XFree(name);
        }
        if (!found) found = findWindow(display, children[i], prefix);
    }
    if (children) XFree(children);
    return found;
}

// The window may be gone by the time it is mapped again (the lesson ran its frames and closed): that
// is the lesson's business, not an error of this tool.
int ignoreErrors(Display*, XErrorEvent*) {
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 3) {
        std::fprintf(stderr, "usage: fx_unmap_window <title prefix> <seconds hidden>\n");
        return 2;
    }
    Display* display = XOpenDisplay(nullptr);
    if (!display) {
        std::fprintf(stderr, "no X display\n");
        return 1;
    }
    XSetErrorHandler(ignoreErrors);
    const std::string prefix = argv[1];
    Window window = 0;
    for (int tries = 0; tries < 400 && !window; ++tries) {
        window = findWindow(display, DefaultRootWindow(display), prefix);
        if (!window) std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    if (!window) {
        std::fprintf(stderr, "no window named \"%s...\" appeared\n", prefix.c_str());
        return 1;
    }
    // The name is set before the window is first mapped: unmapping it then would do nothing.
    for (int tries = 0; tries < 400; ++tries) {
        XWindowAttributes attributes;
        if (XGetWindowAttributes(display, window, &attributes) && attributes.map_state == IsViewable) break;
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(200));  // a few frames drawn first
    XUnmapWindow(display, window);
    XFlush(display);
    std::printf("unmapped \"%s...\" for %s s\n", prefix.c_str(), argv[2]);
    std::this_thread::sleep_for(std::chrono::duration<double>(std::atof(argv[2])));
    XMapWindow(display, window);
    XFlush(display);
    XCloseDisplay(display);
    return 0;
}

#include "gl/live_objects.hpp"

#include <algorithm>

#include "base/log.hpp"
#include "gl/gl.hpp"

namespace fx::gl {
namespace {

// Counts the names for which `alive` holds, from 1 up to `bound` and on past it while live names keep
// turning up (a driver that reuses freed names can give a fresh name below live ones).
template <class Alive>
int countNames(GLuint bound, Alive alive) {
    constexpr GLuint kPastTheBound = 1024;
    int count = 0;
    GLuint lastLive = 0;
    for (GLuint name = 1; name < bound || name <= lastLive + kPastTheBound; ++name) {
        if (alive(name)) {
            ++count;
            lastLive = name;
        }
    }
    return count;
}

// The name a fresh object of a kind gets now: made and deleted at once.
template <class Make, class Delete>
GLuint nextName(Make make, Delete destroy) {
    GLuint name = 0;
    make(&name);
    destroy(&name);
    return name;
}

}  // namespace

int LiveObjects::total() const {
    return textures + buffers + framebuffers + renderbuffers + vertexArrays + samplers + queries + programs +
           shaders + transformFeedbacks;
}

LiveObjects countLiveObjects() {
    LiveObjects o;
    auto isTrue = [](GLboolean b) { return b == GL_TRUE; };
    GLuint bound = nextName([](GLuint* n) { glCreateTextures(GL_TEXTURE_2D, 1, n); },
                            [](GLuint* n) { glDeleteTextures(1, n); });
    o.textures = countNames(bound, [&](GLuint n) { return isTrue(glIsTexture(n)); });
    bound = nextName([](GLuint* n) { glCreateBuffers(1, n); }, [](GLuint* n) { glDeleteBuffers(1, n); });
    o.buffers = countNames(bound, [&](GLuint n) { return isTrue(glIsBuffer(n)); });
    bound = nextName([](GLuint* n) { glCreateFramebuffers(1, n); },
                     [](GLuint* n) { glDeleteFramebuffers(1, n); });
    o.framebuffers = countNames(bound, [&](GLuint n) { return isTrue(glIsFramebuffer(n)); });
    bound = nextName([](GLuint* n) { glCreateRenderbuffers(1, n); },
                     [](GLuint* n) { glDeleteRenderbuffers(1, n); });
    o.renderbuffers = countNames(bound, [&](GLuint n) { return isTrue(glIsRenderbuffer(n)); });
    bound = nextName([](GLuint* n) { glCreateVertexArrays(1, n); },
                     [](GLuint* n) { glDeleteVertexArrays(1, n); });
    o.vertexArrays = countNames(bound, [&](GLuint n) { return isTrue(glIsVertexArray(n)); });
    bound = nextName([](GLuint* n) { glCreateSamplers(1, n); }, [](GLuint* n) { glDeleteSamplers(1, n); });
    o.samplers = countNames(bound, [&](GLuint n) { return isTrue(glIsSampler(n)); });
    bound = nextName([](GLuint* n) { glCreateQueries(GL_TIME_ELAPSED, 1, n); },
                     [](GLuint* n) { glDeleteQueries(1, n); });
    o.queries = countNames(bound, [&](GLuint n) { return isTrue(glIsQuery(n)); });
    bound = nextName([](GLuint* n) { glCreateTransformFeedbacks(1, n); },
                     [](GLuint* n) { glDeleteTransformFeedbacks(1, n); });
    o.transformFeedbacks = countNames(bound, [&](GLuint n) { return isTrue(glIsTransformFeedback(n)); });
    // Programs and shaders share one namespace.
    bound =
        std::max(nextName([](GLuint* n) { *n = glCreateProgram(); }, [](GLuint* n) { glDeleteProgram(*n); }),
                 nextName([](GLuint* n) { *n = glCreateShader(GL_VERTEX_SHADER); },
                          [](GLuint* n) { glDeleteShader(*n); }));
    o.programs = countNames(bound, [&](GLuint n) { return isTrue(glIsProgram(n)); });
    o.shaders = countNames(bound, [&](GLuint n) { return isTrue(glIsShader(n)); });
    return o;
}

std::string liveObjectsCsvHeader() {
    return "textures,buffers,framebuffers,renderbuffers,vertexArrays,samplers,queries,programs,shaders,"
           "transformFeedbacks";
}

std::string liveObjectsCsvRow(const LiveObjects& o) {
    return cat(o.textures, ",", o.buffers, ",", o.framebuffers, ",", o.renderbuffers, ",", o.vertexArrays,
               ",", o.samplers, ",", o.queries, ",", o.programs, ",", o.shaders, ",", o.transformFeedbacks);
}

}  // namespace fx::gl

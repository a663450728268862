#include "renderer/relay_sinks.hpp"

#include <utility>

namespace signstim::render {

void StillCapturingSink::push(Image&& frame) {
    if (count_++ == keep_) still_ = frame;
    next_.push(std::move(frame));
}

void TeeSink::push(Image&& frame) {
    first_.push(Image(frame));
    second_.push(std::move(frame));
    ++count_;
}

void TeeSink::finish() {
    first_.finish();
    second_.finish();
}

}  // namespace signstim::render

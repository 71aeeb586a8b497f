#pragma once

namespace fx {

// How pass times are measured, as asked for with --timing (Automatic picks by renderer).
enum class TimingMode { Automatic, Gpu, Fenced, Off };

}  // namespace fx

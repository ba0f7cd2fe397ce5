// Deprecated include path of hinf_cpp 0.1, kept for the 0.2 releases and removed in 0.3: include
// "hinf/io/files.hpp" and "hinf/io/model_kinds.hpp" and "hinf/io/results.hpp" and "hinf/io/scenario_file.hpp" instead.
// Define HINF_NO_DEPRECATED_HEADER_MESSAGES to silence the note.
#pragma once
#ifndef HINF_NO_DEPRECATED_HEADER_MESSAGES
#pragma message("hinf/scenario_io.hpp is deprecated (removed in hinf_cpp 0.3): include \"hinf/io/files.hpp\" and \"hinf/io/model_kinds.hpp\" and \"hinf/io/results.hpp\" and \"hinf/io/scenario_file.hpp\"")
#endif
#include "hinf/io/files.hpp"
#include "hinf/io/model_kinds.hpp"
#include "hinf/io/results.hpp"
#include "hinf/io/scenario_file.hpp"

// Deprecated include path of hinf_cpp 0.1, kept for the 0.2 releases and removed in 0.3: include
// "hinf/numerics/cvode.hpp" instead.
// Define HINF_NO_DEPRECATED_HEADER_MESSAGES to silence the note.
#pragma once
#ifndef HINF_NO_DEPRECATED_HEADER_MESSAGES
#pragma message("hinf/cvode.hpp is deprecated (removed in hinf_cpp 0.3): include \"hinf/numerics/cvode.hpp\"")
#endif
#include "hinf/numerics/cvode.hpp"

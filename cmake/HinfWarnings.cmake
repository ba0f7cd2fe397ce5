# hinf_set_warnings(target): the warning level every C++ source of the project builds with. C
# sources (the built-in vehicles' CasADi generated code, cpp/src/models/generated) are not ours to
# warn about.
function(hinf_set_warnings target)
  if(CMAKE_CXX_COMPILER_ID MATCHES "GNU|Clang")
    target_compile_options(${target} PRIVATE
                           $<$<COMPILE_LANGUAGE:CXX>:-Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor>)
  endif()
endfunction()

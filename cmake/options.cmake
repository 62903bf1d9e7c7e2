# Compile options shared by every swarmpath target (linked as swarm_options).
add_library(swarm_options INTERFACE)
target_compile_options(swarm_options INTERFACE
  -Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wimplicit-fallthrough -Wold-style-cast
  -Wnon-virtual-dtor
  # determinism: no fused multiply-add contraction, no fast-math, no -march=native
  -ffp-contract=off
  # position-independent code (for the Python module) that still inlines and calls directly
  -fno-semantic-interposition)

if(SWARM_WERROR)
  set(CMAKE_COMPILE_WARNING_AS_ERROR ON)
endif()

if(SWARM_SANITIZE)
  add_compile_options(-fsanitize=${SWARM_SANITIZE} -fno-sanitize-recover=all -fno-omit-frame-pointer)
  add_link_options(-fsanitize=${SWARM_SANITIZE})
endif()

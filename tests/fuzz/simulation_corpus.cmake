# The seed corpus of simulation_fuzz: every text board of fixtures/boards/{gizmos,scenes} and the
# spec example, each twice, with the header of simulation_fuzz.cpp in front: once in the ballistic
# model with a maximum tick of 0.05 s, once in the classic model with 0.01 s, both for 0.5 s of
# board time with fixtures/keys/flippers.keys as the key script.
#   cmake -DFIXTURES=fixtures -DOUT=DIR -P tests/fuzz/simulation_corpus.cmake
# CMake runs it at configure time for the corpus runner; scripts/fuzz-run.sh for libFuzzer.
if(NOT FIXTURES OR NOT OUT)
  message(FATAL_ERROR "simulation_corpus.cmake: set FIXTURES (the fixtures folder) and OUT (where to write)")
endif()
file(GLOB boards ${FIXTURES}/boards/gizmos/*.txt ${FIXTURES}/boards/scenes/*.txt ${FIXTURES}/boards/spec-example.txt)
list(SORT boards)
file(READ ${FIXTURES}/keys/flippers.keys keys)
file(MAKE_DIRECTORY ${OUT})
file(GLOB stale ${OUT}/*.run)
if(stale)
  file(REMOVE ${stale})
endif()
foreach(board IN LISTS boards)
  get_filename_component(name ${board} NAME_WE)
  file(READ ${board} text)
  file(WRITE ${OUT}/${name}-ballistic.run "run ballistic 0.05 0.5\n${keys}board\n${text}")
  file(WRITE ${OUT}/${name}-classic.run "run classic 0.01 0.5\n${keys}board\n${text}")
endforeach()

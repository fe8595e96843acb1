# What the study tests check of every chart. Include after gizmo_cli.cmake.

# Fails unless OUT/charts/NAME.svg was written, is an SVG (drawn by gnuplot), and the page's
# text `html` shows it.
function(study_check_chart out name html)
  set(svg ${out}/charts/${name}.svg)
  if(NOT EXISTS ${svg})
    gizmo_fail("charts/${name}.svg was not written")
  endif()
  file(READ ${svg} text LIMIT 2000)
  if(NOT text MATCHES "<svg")
    gizmo_fail("charts/${name}.svg is not an SVG")
  endif()
  string(FIND "${html}" "charts/${name}.svg" at)
  if(at LESS 0)
    gizmo_fail("index.html does not show charts/${name}.svg")
  endif()
endfunction()

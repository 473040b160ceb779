# Checks vtkao quality's re-trace of HAO's outliers on the surface the rasterizer shows
# (quality.json's hao_outliers_rasterized_surface; Documentation/quality.md, "HAO's outliers
# on the surface the rasterizer shows"). On glyphs and fins (binary falloff) most of HAO's
# outliers are found on the rasterized surface and agree with the integral there:
# with the depth read back wrongly (its rows flipped) no triangle is found, and with the
# G-buffer plane not compared another face is taken; either way the test fails.
#   cmake -DJSON=quality.json -DMIN_AGREE=N -P CheckRasterizedSurfaces.cmake
file(READ "${JSON}" json)
string(JSON scenes LENGTH "${json}" scenes)
set(agree 0)
set(rest 0)
math(EXPR last "${scenes} - 1")
foreach (i RANGE ${last})
  string(JSON name GET "${json}" scenes ${i} name)
  string(JSON a GET "${json}" scenes ${i} hao_outliers_rasterized_surface agree)
  string(JSON o GET "${json}" scenes ${i} hao_outliers_rasterized_surface off)
  string(JSON u GET "${json}" scenes ${i} hao_outliers_rasterized_surface unresolved)
  message(STATUS "${name}: HAO's outliers on the rasterized surface: ${a} agree, ${o} off, "
    "${u} unresolved")
  math(EXPR agree "${agree} + ${a}")
  math(EXPR rest "${rest} + ${o} + ${u}")
endforeach ()
if (agree LESS MIN_AGREE OR NOT agree GREATER rest)
  message(FATAL_ERROR "only ${agree} of HAO's outliers agree with the integral on the "
    "rasterized surface (expected at least ${MIN_AGREE}, and more than the ${rest} others)")
endif ()

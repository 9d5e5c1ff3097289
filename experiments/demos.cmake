# demos.cmake - the drivers of the paper's demonstration figures 1-4 (demos)
# and of the C-obstacle experiment, Table 2 and Fig. 9 (cobstacle), with
# their tests. Included from experiments/CMakeLists.txt.

# demos: the geometry of figures 1-4 as CSV, exactly the paper's parameters.
add_executable(demos ${CMAKE_CURRENT_LIST_DIR}/demos.c)
target_link_libraries(demos PRIVATE mink_exp m)
target_compile_options(demos PRIVATE ${MINK_C_WARNINGS})

# cobstacle: C-obstacle timings (Table 2) and the geometry of Fig. 9.
add_executable(cobstacle ${CMAKE_CURRENT_LIST_DIR}/cobstacle.c)
target_link_libraries(cobstacle PRIVATE mink_exp m)
target_compile_options(cobstacle PRIVATE ${MINK_C_WARNINGS})

# Helper functions: one target per module, project warnings, sanitizers.

# hs_set_warnings(target): the project's warning set; errors when HS_WERROR is on.
function(hs_set_warnings target)
    target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wsign-conversion
                                             -Wno-sign-conversion)
    if(HS_WERROR)
        target_compile_options(${target} PRIVATE -Werror)
    endif()
    if(HS_SANITIZE)
        target_compile_options(${target} PRIVATE -fsanitize=address,undefined -fno-omit-frame-pointer
                                                 -fno-sanitize-recover=undefined)
        target_link_options(${target} PRIVATE -fsanitize=address,undefined)
    endif()
endfunction()

# hs_module(NAME name SOURCES ... [PUBLIC_DEPS ...] [PRIVATE_DEPS ...])
# Creates library hs_<name> with alias hs::<name>; public headers in include/, sources in src/.
function(hs_module)
    cmake_parse_arguments(M "" "NAME" "SOURCES;PUBLIC_DEPS;PRIVATE_DEPS" ${ARGN})
    add_library(hs_${M_NAME} STATIC ${M_SOURCES})
    add_library(hs::${M_NAME} ALIAS hs_${M_NAME})
    target_include_directories(hs_${M_NAME} PUBLIC ${CMAKE_CURRENT_SOURCE_DIR}/include
                                            PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/src)
    target_link_libraries(hs_${M_NAME} PUBLIC ${M_PUBLIC_DEPS} PRIVATE ${M_PRIVATE_DEPS})
    set_target_properties(hs_${M_NAME} PROPERTIES POSITION_INDEPENDENT_CODE ON)
    hs_set_warnings(hs_${M_NAME})
endfunction()

# hs_executable(NAME name SOURCES ... [DEPS ...]): an executable with the project's warnings.
function(hs_executable)
    cmake_parse_arguments(E "" "NAME" "SOURCES;DEPS" ${ARGN})
    add_executable(${E_NAME} ${E_SOURCES})
    target_link_libraries(${E_NAME} PRIVATE ${E_DEPS})
    hs_set_warnings(${E_NAME})
endfunction()

# hs_gtest(NAME name SOURCES ... DEPS ... [LABELS ...]): a GoogleTest binary registered with ctest.
function(hs_gtest)
    cmake_parse_arguments(T "" "NAME" "SOURCES;DEPS;LABELS" ${ARGN})
    add_executable(${T_NAME} ${T_SOURCES})
    target_link_libraries(${T_NAME} PRIVATE ${T_DEPS} hs_test_support GTest::gtest GTest::gtest_main)
    hs_set_warnings(${T_NAME})
    if(NOT T_LABELS)
        set(T_LABELS unit)
    endif()
    add_test(NAME ${T_NAME} COMMAND ${T_NAME})
    math(EXPR timeout "600 * ${HS_TEST_TIMEOUT_SCALE}")
    set_tests_properties(${T_NAME} PROPERTIES LABELS "${T_LABELS}" TIMEOUT ${timeout}
        ENVIRONMENT "HS_SHARED_DATA_DIR=${HS_SHARED_DATA_DIR};HS_TEST_DATA_DIR=${PROJECT_SOURCE_DIR}/tests/data")
endfunction()

# hs_qtest(NAME name SOURCES ... DEPS ...): a Qt Test binary registered with ctest, label "gui".
# These tests open windows with OpenGL: they need an X display (the test command runs ctest under xvfb-run -a;
# the offscreen platform has no GL for VTK).
function(hs_qtest)
    cmake_parse_arguments(T "" "NAME" "SOURCES;DEPS" ${ARGN})
    add_executable(${T_NAME} ${T_SOURCES})
    set_target_properties(${T_NAME} PROPERTIES AUTOMOC ON)
    target_include_directories(${T_NAME} PRIVATE ${PROJECT_SOURCE_DIR}/tests/widgets/support)
    target_link_libraries(${T_NAME} PRIVATE ${T_DEPS} Qt6::Test)
    hs_set_warnings(${T_NAME})
    vtk_module_autoinit(TARGETS ${T_NAME} MODULES ${VTK_LIBRARIES})
    add_test(NAME ${T_NAME} COMMAND ${T_NAME})
    # One at a time: they share the X server, and keyboard shortcuts need their window to stay active.
    set_tests_properties(${T_NAME} PROPERTIES LABELS gui TIMEOUT 300 RESOURCE_LOCK x_display
        ENVIRONMENT "QT_QPA_PLATFORM=xcb;HS_SHARED_DATA_DIR=${HS_SHARED_DATA_DIR};HS_TEST_DATA_DIR=${PROJECT_SOURCE_DIR}/tests/data")
endfunction()

# hs_header_version(OUT HEADER REGEX): the version a header states in its text, for libraries without a version macro
# (tinygltf, minizip, TetGen). REGEX has one capture group, the version; OUT is empty when the header says nothing.
function(hs_header_version out header regex)
    set(version "")
    if(EXISTS "${header}")
        file(STRINGS "${header}" lines REGEX "${regex}" LIMIT_COUNT 1)
        if(lines MATCHES "${regex}")
            set(version "${CMAKE_MATCH_1}")
        endif()
    endif()
    set(${out} "${version}" PARENT_SCOPE)
endfunction()

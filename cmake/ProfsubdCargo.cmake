# Builds the Rust library with cargo and exposes it as imported targets:
#   profsubd::profsubd         shared library (SONAME libprofsubd.so.<major>, set by build.rs)
#   profsubd::profsubd_static  static library with the system libraries Rust's std needs
# Nothing is downloaded at configure time; cargo runs at build time (offline when
# PROFSUBD_CARGO_OFFLINE is ON). The artifacts are copied to <build>/lib with the usual
# versioned names so that the harness and the install step use exactly what gets installed.

find_program(CARGO_EXECUTABLE cargo HINTS "$ENV{CARGO_HOME}/bin" "$ENV{HOME}/.cargo/bin" REQUIRED)

set(PROFSUBD_CARGO_PROFILE "release" CACHE STRING "cargo profile used to build the library (release or dev)")
set(PROFSUBD_CARGO_TARGET_DIR "${CMAKE_SOURCE_DIR}/target" CACHE PATH
    "cargo target directory (shared with plain cargo builds to avoid compiling twice)")
option(PROFSUBD_CARGO_OFFLINE "Pass --offline to cargo" OFF)
# E.g. --tests: cargo then resolves features as `cargo test` does (dev-dependencies unify
# some features), so a build tree shared with `cargo test --release` reuses its library
# instead of compiling a second variant. scripts/test_all.sh does this.
set(PROFSUBD_CARGO_EXTRA_ARGS "" CACHE STRING "Extra arguments for cargo build (a ;-list)")

if(PROFSUBD_CARGO_PROFILE STREQUAL "dev")
  set(_profsubd_profile_dir debug)
else()
  set(_profsubd_profile_dir ${PROFSUBD_CARGO_PROFILE})
endif()
set(_profsubd_cargo_out "${PROFSUBD_CARGO_TARGET_DIR}/${_profsubd_profile_dir}")

set(PROFSUBD_LIB_DIR "${CMAKE_BINARY_DIR}/lib")
set(PROFSUBD_SONAME "libprofsubd.so.${PROJECT_VERSION_MAJOR}")
set(PROFSUBD_SHARED_REAL "libprofsubd.so.${PROJECT_VERSION}")
set(PROFSUBD_INCLUDE_DIR "${CMAKE_SOURCE_DIR}/include")

set(_profsubd_cargo_args build --lib --profile ${PROFSUBD_CARGO_PROFILE}
    --manifest-path "${CMAKE_SOURCE_DIR}/Cargo.toml")
if(PROFSUBD_CARGO_OFFLINE)
  list(APPEND _profsubd_cargo_args --offline)
endif()
list(APPEND _profsubd_cargo_args ${PROFSUBD_CARGO_EXTRA_ARGS})

# Always runs: cargo itself decides whether anything is out of date.
add_custom_target(profsubd_cargo ALL
  COMMAND ${CMAKE_COMMAND} -E env "CARGO_TARGET_DIR=${PROFSUBD_CARGO_TARGET_DIR}"
          "${CARGO_EXECUTABLE}" ${_profsubd_cargo_args}
  COMMAND ${CMAKE_COMMAND} -E make_directory "${PROFSUBD_LIB_DIR}"
  COMMAND ${CMAKE_COMMAND} -E copy_if_different "${_profsubd_cargo_out}/libprofsubd.so"
          "${PROFSUBD_LIB_DIR}/${PROFSUBD_SHARED_REAL}"
  COMMAND ${CMAKE_COMMAND} -E create_symlink ${PROFSUBD_SHARED_REAL} "${PROFSUBD_LIB_DIR}/${PROFSUBD_SONAME}"
  COMMAND ${CMAKE_COMMAND} -E create_symlink ${PROFSUBD_SONAME} "${PROFSUBD_LIB_DIR}/libprofsubd.so"
  COMMAND ${CMAKE_COMMAND} -E copy_if_different "${_profsubd_cargo_out}/libprofsubd.a"
          "${PROFSUBD_LIB_DIR}/libprofsubd.a"
  BYPRODUCTS "${PROFSUBD_LIB_DIR}/${PROFSUBD_SHARED_REAL}" "${PROFSUBD_LIB_DIR}/${PROFSUBD_SONAME}"
             "${PROFSUBD_LIB_DIR}/libprofsubd.so" "${PROFSUBD_LIB_DIR}/libprofsubd.a"
  WORKING_DIRECTORY "${CMAKE_SOURCE_DIR}"
  USES_TERMINAL
  COMMENT "cargo build --lib --profile ${PROFSUBD_CARGO_PROFILE}")

set(THREADS_PREFER_PTHREAD_FLAG ON)
find_package(Threads REQUIRED)
# What Rust's std needs from the system when linked statically (rustc --print native-static-libs).
set(PROFSUBD_STATIC_SYSTEM_LIBS Threads::Threads ${CMAKE_DL_LIBS} m rt util)

add_library(profsubd_shared SHARED IMPORTED GLOBAL)
set_target_properties(profsubd_shared PROPERTIES
  IMPORTED_LOCATION "${PROFSUBD_LIB_DIR}/${PROFSUBD_SHARED_REAL}"
  IMPORTED_SONAME "${PROFSUBD_SONAME}"
  INTERFACE_INCLUDE_DIRECTORIES "${PROFSUBD_INCLUDE_DIR}")
add_dependencies(profsubd_shared profsubd_cargo)
add_library(profsubd::profsubd ALIAS profsubd_shared)

add_library(profsubd_static STATIC IMPORTED GLOBAL)
set_target_properties(profsubd_static PROPERTIES
  IMPORTED_LOCATION "${PROFSUBD_LIB_DIR}/libprofsubd.a"
  INTERFACE_INCLUDE_DIRECTORIES "${PROFSUBD_INCLUDE_DIR}"
  INTERFACE_LINK_LIBRARIES "${PROFSUBD_STATIC_SYSTEM_LIBS}")
add_dependencies(profsubd_static profsubd_cargo)
add_library(profsubd::profsubd_static ALIAS profsubd_static)

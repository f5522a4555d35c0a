# Third-party dependencies, all from Debian 12 packages (scripts/install-deps.sh).
find_package(Eigen3 3.3 REQUIRED NO_MODULE)
find_package(nlohmann_json 3.10 REQUIRED)
find_package(yaml-cpp REQUIRED)
find_package(Threads REQUIRED)
find_package(OpenCV 4 REQUIRED COMPONENTS core imgproc imgcodecs videoio)

# Bullet in double precision. Debian's BulletConfig-float64.cmake carries
# relative paths, so the imported target is spelled out here; the float and
# float64 libraries must never be mixed in one binary.
find_path(ACCSIM_BULLET_INCLUDE_DIR btBulletDynamicsCommon.h PATH_SUFFIXES bullet REQUIRED)
foreach(_lib BulletDynamics BulletCollision LinearMath)
  find_library(ACCSIM_${_lib}_LIB ${_lib}-float64 REQUIRED)
endforeach()
if(NOT TARGET accsim::bullet)
  add_library(accsim_bullet INTERFACE)
  add_library(accsim::bullet ALIAS accsim_bullet)
  target_include_directories(accsim_bullet SYSTEM INTERFACE ${ACCSIM_BULLET_INCLUDE_DIR})
  target_compile_definitions(accsim_bullet INTERFACE BT_USE_DOUBLE_PRECISION)
  target_link_libraries(accsim_bullet INTERFACE
    ${ACCSIM_BulletDynamics_LIB} ${ACCSIM_BulletCollision_LIB} ${ACCSIM_LinearMath_LIB})
endif()

find_path(ACCSIM_CLI11_INCLUDE_DIR CLI/CLI.hpp REQUIRED)
if(NOT TARGET accsim::cli11)
  add_library(accsim_cli11 INTERFACE)
  add_library(accsim::cli11 ALIAS accsim_cli11)
  target_include_directories(accsim_cli11 SYSTEM INTERFACE ${ACCSIM_CLI11_INCLUDE_DIR})
endif()

# `cmake --install` (with BP_INSTALL, the default) installs the patched Bullet where and as upstream's
# CMake installs Bullet, so it replaces an upstream install:
#   lib/      LinearMath, Bullet3Common, BulletCollision, BulletDynamics, BulletInverseDynamics, BulletSoftBody
#             (static; shared with BUILD_SHARED_LIBS=ON, libBulletDynamics.so.<version> as upstream's)
#   include/bullet/   btBulletCollisionCommon.h, btBulletDynamicsCommon.h and <library>/... as upstream lays
#             them out (with upstream's extra copies of the common headers in the library folders), and also
#             BulletInverseDynamics' .hpp headers, which upstream's "*.h" pattern leaves out
#   lib/cmake/bullet/ BulletConfig.cmake (upstream's BULLET_* variables, imported targets Bullet::<library>),
#             BulletConfigVersion.cmake, UseBullet.cmake
#   lib/pkgconfig/bullet.pc
# A consumer finds it with CMake's own FindBullet module (plain find_package(Bullet)), with
# find_package(Bullet CONFIG) or with pkg-config (tests/pipeline/install_consumers.cmake checks all three).
include(GNUInstallDirs)

set(BULLET_VERSION_STRING "${BULLET_UPSTREAM_VERSION_STRING}")

install(TARGETS ${BP_INSTALLED_LIBRARIES}
	EXPORT BulletPlasticityTargets
	RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR}
	ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
	LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
foreach(dir IN LISTS BP_INSTALLED_LIBRARIES)
	install(DIRECTORY "${BULLET_TREE}/src/${dir}" DESTINATION include/bullet
		FILES_MATCHING PATTERN "*.h" PATTERN "*.hpp")
endforeach()
install(FILES "${BULLET_TREE}/src/btBulletCollisionCommon.h" "${BULLET_TREE}/src/btBulletDynamicsCommon.h"
	DESTINATION include/bullet)
# upstream's src/*/CMakeLists.txt also copy the common headers into these folders
install(FILES "${BULLET_TREE}/src/btBulletCollisionCommon.h" DESTINATION include/bullet/BulletCollision)
install(FILES "${BULLET_TREE}/src/btBulletCollisionCommon.h" DESTINATION include/bullet/BulletInverseDynamics)
install(FILES "${BULLET_TREE}/src/btBulletDynamicsCommon.h" DESTINATION include/bullet/BulletDynamics)
install(EXPORT BulletPlasticityTargets NAMESPACE Bullet:: DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/bullet)

if(BP_USE_DOUBLE_PRECISION)
	set(BULLET_DOUBLE_DEF "-DBT_USE_DOUBLE_PRECISION")
	set(BULLET_USE_DOUBLE_PRECISION ON)
else()
	set(BULLET_DOUBLE_DEF "")
	set(BULLET_USE_DOUBLE_PRECISION OFF)
endif()
configure_file(cmake/BulletConfig.cmake.in "${PROJECT_BINARY_DIR}/BulletConfig.cmake" @ONLY)
configure_file(cmake/BulletConfigVersion.cmake.in "${PROJECT_BINARY_DIR}/BulletConfigVersion.cmake" @ONLY)
install(FILES "${PROJECT_BINARY_DIR}/BulletConfig.cmake" "${PROJECT_BINARY_DIR}/BulletConfigVersion.cmake"
	cmake/UseBullet.cmake DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/bullet)
# The prefix is substituted at install time so `cmake --install --prefix X` is honoured.
install(CODE "
	set(prefix \"\${CMAKE_INSTALL_PREFIX}\")
	set(libdir \"${CMAKE_INSTALL_LIBDIR}\")
	set(BULLET_VERSION_STRING \"${BULLET_VERSION_STRING}\")
	set(BULLET_DOUBLE_DEF \"${BULLET_DOUBLE_DEF}\")
	configure_file(\"${PROJECT_SOURCE_DIR}/cmake/bullet.pc.in\" \"\$ENV{DESTDIR}\${prefix}/\${libdir}/pkgconfig/bullet.pc\" @ONLY)
	message(STATUS \"Installing: \$ENV{DESTDIR}\${prefix}/\${libdir}/pkgconfig/bullet.pc\")
")

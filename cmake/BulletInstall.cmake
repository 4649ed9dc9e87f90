# `cmake --install` installs the patched Bullet like a normal Bullet install:
# headers in include/bullet, static libraries in lib, BulletConfig.cmake for
# find_package(Bullet) (BULLET_INCLUDE_DIRS, BULLET_LIBRARIES, ... as upstream's)
# and bullet.pc for pkg-config.
include(GNUInstallDirs)

set(BULLET_VERSION_STRING "${BULLET_UPSTREAM_VERSION_STRING}")

install(TARGETS LinearMath BulletCollision BulletDynamics
	EXPORT BulletPlasticityTargets
	ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
	LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
foreach(dir LinearMath BulletCollision BulletDynamics)
	install(DIRECTORY "${BULLET_TREE}/src/${dir}" DESTINATION include/bullet
		FILES_MATCHING PATTERN "*.h" PATTERN ".pc" EXCLUDE)
endforeach()
install(FILES "${BULLET_TREE}/src/btBulletCollisionCommon.h" "${BULLET_TREE}/src/btBulletDynamicsCommon.h"
	DESTINATION include/bullet)
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
	DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/bullet)
# The prefix is substituted at install time so `cmake --install --prefix X` is honoured.
install(CODE "
	set(prefix \"\${CMAKE_INSTALL_PREFIX}\")
	set(libdir \"${CMAKE_INSTALL_LIBDIR}\")
	set(BULLET_VERSION_STRING \"${BULLET_VERSION_STRING}\")
	set(BULLET_DOUBLE_DEF \"${BULLET_DOUBLE_DEF}\")
	configure_file(\"${PROJECT_SOURCE_DIR}/cmake/bullet.pc.in\" \"\$ENV{DESTDIR}\${prefix}/\${libdir}/pkgconfig/bullet.pc\" @ONLY)
	message(STATUS \"Installing: \$ENV{DESTDIR}\${prefix}/\${libdir}/pkgconfig/bullet.pc\")
")

# LinearMath, BulletCollision and BulletDynamics from the patched tree ${BULLET_TREE}.
# The sdist has no CMake files for them, so the sources are globbed per library the
# way upstream's own src/*/CMakeLists.txt list them (every .cpp below the folder).

set(BULLET_DEFINITIONS "")
if(BP_USE_DOUBLE_PRECISION)
	list(APPEND BULLET_DEFINITIONS BT_USE_DOUBLE_PRECISION)
endif()

function(bp_add_bullet_library name)
	file(GLOB_RECURSE sources CONFIGURE_DEPENDS "${BULLET_TREE}/src/${name}/*.cpp")
	add_library(${name} STATIC ${sources})
	target_include_directories(${name} PUBLIC
		$<BUILD_INTERFACE:${BULLET_TREE}/src>
		$<INSTALL_INTERFACE:include/bullet>)
	target_compile_definitions(${name} PUBLIC ${BULLET_DEFINITIONS})
	# Upstream code is compiled as upstream ships it; its warnings are not ours to fix here.
	target_compile_options(${name} PRIVATE -w)
	set_target_properties(${name} PROPERTIES CXX_STANDARD 11)
	if(BP_UNITY_BUILD)
		set_target_properties(${name} PROPERTIES UNITY_BUILD ON UNITY_BUILD_BATCH_SIZE 16)
	endif()
	add_library(Bullet::${name} ALIAS ${name})
endfunction()

bp_add_bullet_library(LinearMath)
bp_add_bullet_library(BulletCollision)
bp_add_bullet_library(BulletDynamics)
target_link_libraries(BulletCollision PUBLIC LinearMath)
target_link_libraries(BulletDynamics PUBLIC BulletCollision)

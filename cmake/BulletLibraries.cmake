# LinearMath, BulletCollision and BulletDynamics from the patched tree ${BULLET_TREE}.
# The sdist has no CMake files for them, so the sources are globbed per library the
# way upstream's own src/*/CMakeLists.txt list them (every .cpp below the folder).

set(BULLET_DEFINITIONS "")
if(BP_USE_DOUBLE_PRECISION)
	list(APPEND BULLET_DEFINITIONS BT_USE_DOUBLE_PRECISION)
endif()

# bp_add_bullet_library(<target> <tree> <folder>): the library <folder> (e.g. BulletDynamics)
# of the Bullet tree <tree>, as the static library <target>.
function(bp_add_bullet_library name tree folder)
	file(GLOB_RECURSE sources CONFIGURE_DEPENDS "${tree}/src/${folder}/*.cpp")
	add_library(${name} STATIC ${sources})
	# BEFORE: a second tree's headers (tests' unpatched BulletDynamics) win over the first's.
	target_include_directories(${name} BEFORE PUBLIC
		$<BUILD_INTERFACE:${tree}/src>
		$<INSTALL_INTERFACE:include/bullet>)
	target_compile_definitions(${name} PUBLIC ${BULLET_DEFINITIONS})
	# Upstream code is compiled as upstream ships it; its warnings are not ours to fix here.
	target_compile_options(${name} PRIVATE -w)
	set_target_properties(${name} PROPERTIES CXX_STANDARD 11)
	if(BP_UNITY_BUILD)
		set_target_properties(${name} PROPERTIES UNITY_BUILD ON UNITY_BUILD_BATCH_SIZE 16)
	endif()
endfunction()

bp_add_bullet_library(LinearMath "${BULLET_TREE}" LinearMath)
bp_add_bullet_library(BulletCollision "${BULLET_TREE}" BulletCollision)
bp_add_bullet_library(BulletDynamics "${BULLET_TREE}" BulletDynamics)
foreach(name LinearMath BulletCollision BulletDynamics)
	add_library(Bullet::${name} ALIAS ${name})
endforeach()
target_link_libraries(BulletCollision PUBLIC LinearMath)
target_link_libraries(BulletDynamics PUBLIC BulletCollision)

# LinearMath, BulletCollision and BulletDynamics from the patched tree ${BULLET_TREE}.
# The sdist has no CMake files for them, so the sources are globbed per library the
# way upstream's own src/*/CMakeLists.txt list them (every .cpp below the folder).

set(BULLET_DEFINITIONS "")
if(BP_USE_DOUBLE_PRECISION)
	list(APPEND BULLET_DEFINITIONS BT_USE_DOUBLE_PRECISION)
endif()

# bp_add_bullet_library(<target> <tree> <folder>): the library <folder> (e.g. BulletDynamics)
# of the Bullet tree <tree>, as the static library <target>.
# The files the series adds to the tree are this project's own: they are compiled with warnings (as errors
# with BP_WARNINGS_AS_ERRORS), in an object library of their own; upstream's files keep -w.
set(BP_OWN_BULLET_SOURCES btPlasticConstraintState.cpp btPlasticHingeConstraint.cpp bt6DofElasticPlasticConstraint.cpp
	bt6DofElasticPlastic2Constraint.cpp)

function(bp_add_bullet_library name tree folder)
	file(GLOB_RECURSE sources CONFIGURE_DEPENDS "${tree}/src/${folder}/*.cpp")
	set(own "")
	foreach(source IN LISTS sources)
		get_filename_component(file "${source}" NAME)
		if(file IN_LIST BP_OWN_BULLET_SOURCES)
			list(APPEND own "${source}")
		endif()
	endforeach()
	if(own)
		list(REMOVE_ITEM sources ${own})
		add_library(${name}_own OBJECT ${own})
		target_include_directories(${name}_own PRIVATE ${tree}/src)
		target_compile_definitions(${name}_own PRIVATE ${BULLET_DEFINITIONS})
		target_compile_options(${name}_own PRIVATE -Wall -Wextra $<$<BOOL:${BP_WARNINGS_AS_ERRORS}>:-Werror>)
		set_target_properties(${name}_own PROPERTIES CXX_STANDARD 11 POSITION_INDEPENDENT_CODE ON)
	endif()
	add_library(${name} STATIC ${sources})
	if(own)
		target_sources(${name} PRIVATE $<TARGET_OBJECTS:${name}_own>)
	endif()
	# BEFORE: a second tree's headers (tests' unpatched BulletDynamics) win over the first's.
	# SYSTEM: upstream's headers do not warn in this project's code (its own files warn in ${name}_own)
	target_include_directories(${name} SYSTEM BEFORE PUBLIC
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

# Warnings for this project's own targets (demos, tests): -Wall -Wextra, errors with BP_WARNINGS_AS_ERRORS.
function(bp_project_warnings)
	foreach(target IN LISTS ARGN)
		target_compile_options(${target} PRIVATE -Wall -Wextra $<$<BOOL:${BP_WARNINGS_AS_ERRORS}>:-Werror>)
	endforeach()
endfunction()

# The libraries upstream installs, from the patched tree ${BULLET_TREE}: LinearMath, BulletCollision and
# BulletDynamics (which the project's code links), and Bullet3Common, BulletInverseDynamics and BulletSoftBody
# (built for the install and the ExampleBrowser app only).
# The sdist has no CMake files for them, so the sources are globbed per library; the globs give exactly the
# .cpp files upstream's own src/*/CMakeLists.txt list (checked against bullet3 6c888f4).

set(BULLET_DEFINITIONS "")
if(BP_USE_DOUBLE_PRECISION)
	list(APPEND BULLET_DEFINITIONS BT_USE_DOUBLE_PRECISION)
endif()

# bp_add_bullet_library(<target> <tree> <folder> [INSTALLED]): the library <folder> (e.g. BulletDynamics)
# of the Bullet tree <tree>, as the library <target>. INSTALLED: one of the libraries `cmake --install`
# installs; it is shared with BUILD_SHARED_LIBS=ON, with upstream's VERSION and SOVERSION
# (${BULLET_UPSTREAM_VERSION_STRING}, so libBulletDynamics.so.${BULLET_UPSTREAM_VERSION_STRING}). Without it (the tests' threadsafe and
# unpatched builds) the library is always static.
# The files the series adds to the tree are this project's own: they are compiled with warnings (as errors
# with BP_WARNINGS_AS_ERRORS), in an object library of their own; upstream's files keep -w.
set(BP_OWN_BULLET_SOURCES btPlasticConstraintState.cpp btPlasticHingeConstraint.cpp bt6DofElasticPlasticConstraint.cpp
	bt6DofElasticPlastic2Constraint.cpp)

function(bp_add_bullet_library name tree folder)
	cmake_parse_arguments(PARSE_ARGV 3 arg "INSTALLED" "" "")
	if(arg_UNPARSED_ARGUMENTS)
		message(FATAL_ERROR "bp_add_bullet_library(${name}): unknown arguments ${arg_UNPARSED_ARGUMENTS}")
	endif()
	if(NOT IS_DIRECTORY "${tree}/src/${folder}")
		message(FATAL_ERROR "bp_add_bullet_library(${name}): ${tree}/src/${folder} does not exist (is ${folder} in bullet-upstream/pin.cmake?)")
	endif()
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
	if(arg_INSTALLED AND BUILD_SHARED_LIBS)
		add_library(${name} SHARED ${sources})
		set_target_properties(${name} PROPERTIES VERSION ${BULLET_UPSTREAM_VERSION_STRING} SOVERSION ${BULLET_UPSTREAM_VERSION_STRING})
		# Installed, each finds the libraries it needs beside itself (upstream's install has no run path, so
		# e.g. BulletInverseDynamics did not find Bullet3Common in a prefix outside the loader's paths).
		if(APPLE)
			set_target_properties(${name} PROPERTIES INSTALL_RPATH "@loader_path")
		else()
			set_target_properties(${name} PROPERTIES INSTALL_RPATH "$ORIGIN")
		endif()
	else()
		add_library(${name} STATIC ${sources})
	endif()
	if(own)
		# position-independent (above), so they go into a shared library as well
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

set(BP_INSTALLED_LIBRARIES LinearMath Bullet3Common BulletCollision BulletDynamics BulletInverseDynamics BulletSoftBody)
foreach(name IN LISTS BP_INSTALLED_LIBRARIES)
	bp_add_bullet_library(${name} "${BULLET_TREE}" ${name} INSTALLED)
	add_library(Bullet::${name} ALIAS ${name})
endforeach()
# The dependencies upstream's CMake gives the shared libraries (static ones need them too).
target_link_libraries(BulletCollision PUBLIC LinearMath)
target_link_libraries(BulletDynamics PUBLIC BulletCollision)
target_link_libraries(BulletInverseDynamics PUBLIC Bullet3Common LinearMath)
target_link_libraries(BulletSoftBody PUBLIC BulletDynamics)
# btReducedDeformableContactConstraint.h has no include guard: no unity build for this one
set_target_properties(BulletSoftBody PROPERTIES UNITY_BUILD OFF)
# Nothing of the project links the last three but the ExampleBrowser app (which then builds what it needs):
# without BP_INSTALL a plain build does not compile them.
if(NOT BP_INSTALL)
	set_target_properties(Bullet3Common BulletInverseDynamics BulletSoftBody PROPERTIES EXCLUDE_FROM_ALL ON)
endif()

# Warnings for this project's own targets (demos, tests): -Wall -Wextra, errors with BP_WARNINGS_AS_ERRORS.
function(bp_project_warnings)
	foreach(target IN LISTS ARGN)
		target_compile_options(${target} PRIVATE -Wall -Wextra $<$<BOOL:${BP_WARNINGS_AS_ERRORS}>:-Werror>)
	endforeach()
endfunction()

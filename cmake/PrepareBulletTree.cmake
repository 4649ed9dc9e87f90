# Prepares a patched Bullet tree: fetch + verify + unpack (or copy a user tree), then
# apply a quilt series at fuzz 0. Run as a script:
#
#   cmake -DPROJECT_DIR=<repo> -DDEST=<tree> -DDOWNLOAD_DIR=<cache>
#         [-DSERIES=<patches/series>] [-DARCHIVE=<tar.gz>] [-DSOURCE_DIR=<bullet tree>]
#         [-DLIBRARY_PATHS_ONLY=ON] -P cmake/PrepareBulletTree.cmake
#
# Both path groups of pin.cmake are unpacked (the series patches files of both);
# LIBRARY_PATHS_ONLY=ON unpacks the libraries only (for an unpatched reference tree).
#
# The tree is rebuilt from scratch whenever the stamp (archive checksum or source dir,
# unpacked paths, series and every patch's content) differs; otherwise nothing is done,
# so a re-run never applies a patch twice and never reuses a tree made from another series.
# A new tree is assembled in DEST.tmp and renamed at the end: DEST is whole or absent.

cmake_minimum_required(VERSION 3.16)

foreach(required PROJECT_DIR DEST DOWNLOAD_DIR)
	if(NOT DEFINED ${required})
		message(FATAL_ERROR "PrepareBulletTree: -D${required}=... is required")
	endif()
endforeach()
if(NOT DEFINED SERIES)
	set(SERIES "${PROJECT_DIR}/patches/series")
endif()
include("${PROJECT_DIR}/bullet-upstream/pin.cmake")

set(paths ${BULLET_UPSTREAM_LIBRARY_PATHS})
if(NOT LIBRARY_PATHS_ONLY)
	list(APPEND paths ${BULLET_UPSTREAM_DEMO_PATHS})
endif()

# ---- the stamp: everything the patched tree depends on ----
get_filename_component(series_dir "${SERIES}" DIRECTORY)
if(NOT EXISTS "${SERIES}")
	message(FATAL_ERROR "PrepareBulletTree: series file ${SERIES} does not exist")
endif()
file(STRINGS "${SERIES}" series_lines)
set(patch_names "")
foreach(line IN LISTS series_lines)
	string(STRIP "${line}" line)
	if(line STREQUAL "" OR line MATCHES "^#")
		continue()
	endif()
	string(REGEX REPLACE "[ \t].*$" "" name "${line}")
	if(NOT EXISTS "${series_dir}/${name}")
		message(FATAL_ERROR "PrepareBulletTree: ${SERIES} lists ${name}, which is not in ${series_dir}")
	endif()
	list(APPEND patch_names "${name}")
endforeach()

if(SOURCE_DIR)
	set(origin "source-dir:${SOURCE_DIR}")
else()
	set(origin "archive:${BULLET_UPSTREAM_SHA256}")
endif()
set(stamp_text "${origin}\npaths:${paths}\n")
foreach(name IN LISTS patch_names)
	file(SHA256 "${series_dir}/${name}" sum)
	string(APPEND stamp_text "patch:${name}:${sum}\n")
endforeach()
set(stamp_file "${DEST}/.bullet-plasticity-stamp")

if(EXISTS "${stamp_file}")
	file(READ "${stamp_file}" old_stamp)
	if(old_stamp STREQUAL stamp_text)
		list(LENGTH patch_names n)
		message(STATUS "Bullet tree ${DEST} is up to date (${n} patches already applied)")
		return()
	endif()
	message(STATUS "Bullet tree ${DEST} was made from another series or source: rebuilding it")
endif()

# ---- sources ----
set(work "${DEST}.tmp")
file(REMOVE_RECURSE "${work}")
file(MAKE_DIRECTORY "${work}")

if(SOURCE_DIR)
	if(NOT EXISTS "${SOURCE_DIR}/src/btBulletDynamicsCommon.h")
		message(FATAL_ERROR "BULLET_SOURCE_DIR=${SOURCE_DIR} is not a Bullet tree (no src/btBulletDynamicsCommon.h)")
	endif()
	foreach(p IN LISTS paths)
		if(NOT EXISTS "${SOURCE_DIR}/${p}")
			message(FATAL_ERROR "BULLET_SOURCE_DIR=${SOURCE_DIR} has no ${p}, which the build needs")
		endif()
		get_filename_component(parent "${work}/${p}" DIRECTORY)
		file(COPY "${SOURCE_DIR}/${p}" DESTINATION "${parent}")
	endforeach()
else()
	if(NOT ARCHIVE)
		set(ARCHIVE "${DOWNLOAD_DIR}/${BULLET_UPSTREAM_ARCHIVE}")
	endif()
	if(NOT EXISTS "${ARCHIVE}")
		find_program(PYTHON3 NAMES python3 python)
		if(NOT PYTHON3)
			message(FATAL_ERROR "python3 is needed to download ${BULLET_UPSTREAM_ARCHIVE}: apt-get install python3-pip (or pass -DBULLET_ARCHIVE=/path/to/${BULLET_UPSTREAM_ARCHIVE})")
		endif()
		message(STATUS "Downloading ${BULLET_UPSTREAM_PACKAGE}==${BULLET_UPSTREAM_VERSION} source into ${DOWNLOAD_DIR} (about 80 MB, once)")
		file(MAKE_DIRECTORY "${DOWNLOAD_DIR}")
		execute_process(
			COMMAND "${PYTHON3}" -m pip download --no-deps --no-binary :all: --disable-pip-version-check
				"${BULLET_UPSTREAM_PACKAGE}==${BULLET_UPSTREAM_VERSION}" -d "${DOWNLOAD_DIR}"
			RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
		if(NOT rc EQUAL 0 OR NOT EXISTS "${ARCHIVE}")
			message(FATAL_ERROR "Download of ${BULLET_UPSTREAM_PACKAGE}==${BULLET_UPSTREAM_VERSION} failed (pip exit ${rc}). "
				"Check that pip is installed (apt-get install python3-pip) and that PyPI is reachable, "
				"or download ${BULLET_UPSTREAM_ARCHIVE} yourself and pass -DBULLET_ARCHIVE=/path/to/it.\npip said:\n${out}")
		endif()
	endif()
	file(SHA256 "${ARCHIVE}" sum)
	if(NOT sum STREQUAL BULLET_UPSTREAM_SHA256)
		message(FATAL_ERROR "Checksum mismatch for ${ARCHIVE}:\n  expected ${BULLET_UPSTREAM_SHA256}\n  got      ${sum}\n"
			"Delete the file and configure again to download it anew; if it persists, the pin in bullet-upstream/pin.cmake is wrong.")
	endif()
	set(members "")
	foreach(p IN LISTS paths)
		list(APPEND members "${BULLET_UPSTREAM_TOPDIR}/${p}")
	endforeach()
	execute_process(COMMAND tar -xzf "${ARCHIVE}" -C "${work}" --strip-components=1 ${members}
		RESULT_VARIABLE rc ERROR_VARIABLE err)
	if(NOT rc EQUAL 0)
		message(FATAL_ERROR "Unpacking ${ARCHIVE} failed: ${err}")
	endif()
endif()

# ---- patches ----
find_program(QUILT quilt)
if(NOT QUILT)
	message(FATAL_ERROR "quilt is needed to apply the patch series: apt-get install quilt")
endif()
if(patch_names)
	execute_process(
		COMMAND "${CMAKE_COMMAND}" -E env QUILT_PATCHES=${series_dir} QUILT_SERIES=${SERIES} QUILT_PC=.pc
			"${QUILT}" --quiltrc "${PROJECT_DIR}/ci/quiltrc" push -a --fuzz=0
		WORKING_DIRECTORY "${work}"
		RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
	if(NOT rc EQUAL 0)
		string(REGEX MATCHALL "Applying patch [^\n]*" applying "${out}")
		if(NOT applying)
			# quilt refused the series before applying anything (a patch listed twice, a missing file)
			message(FATAL_ERROR "quilt could not apply the series ${SERIES} in ${work}:\n${out}")
		endif()
		list(GET applying -1 last)
		string(REGEX REPLACE "Applying patch (.*/)?" "" failed_patch "${last}")
		string(REGEX MATCHALL "[^\n]*(FAILED|can't find file|No file to patch|does not apply|malformed)[^\n]*" why "${out}")
		string(REGEX MATCHALL "patching file [^\n]*" files "${out}")
		set(failed_file "?")
		if(files)
			list(GET files -1 failed_file)
		endif()
		string(REPLACE ";" "\n  " why "${why}")
		message(FATAL_ERROR "Patch ${failed_patch} does not apply at fuzz 0 (last file: ${failed_file}):\n  ${why}\n"
			"The tree was left untouched in ${work} for inspection. Refresh the patch against the pinned upstream "
			"(see README, 'Editing a patch').\nquilt said:\n${out}")
	endif()
endif()

file(WRITE "${work}/.bullet-plasticity-stamp" "${stamp_text}")
file(REMOVE_RECURSE "${DEST}")
file(RENAME "${work}" "${DEST}")
list(LENGTH patch_names n)
message(STATUS "Bullet tree ${DEST} prepared, ${n} patches applied")

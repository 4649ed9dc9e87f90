# The pinned upstream Bullet this patch series is made against.
# Read by the top-level CMakeLists.txt and cmake/PrepareBulletTree.cmake; edit only here.
#
# pybullet 3.2.7 is Bullet master just after the 3.25 tag (BT_BULLET_VERSION 326).
# Its src/ is byte-identical to bulletphysics/bullet3 master 6c888f4 apart from the
# build files (src/*/CMakeLists.txt, premake4.lua) that the sdist leaves out.

set(BULLET_UPSTREAM_PACKAGE "pybullet")
set(BULLET_UPSTREAM_VERSION "3.2.7")
set(BULLET_UPSTREAM_BT_VERSION "326")
# Upstream's BULLET_VERSION for this tree: bullet3's VERSION file at 6c888f4 says 3.27 (the sdist has no
# VERSION file; btScalar.h's BT_BULLET_VERSION was left at 326). Upstream's CMake makes it the libraries'
# VERSION and SOVERSION (libBulletDynamics.so.3.27) and BULLET_VERSION_STRING / bullet.pc's Version; so does ours.
set(BULLET_UPSTREAM_VERSION_STRING "3.27")
set(BULLET_UPSTREAM_ARCHIVE "pybullet-3.2.7.tar.gz")
set(BULLET_UPSTREAM_ARCHIVE_BYTES 80508379)
set(BULLET_UPSTREAM_SHA256 "042879db8d101ac7590dee475fc6aded508b85fe1273fdbbfde1d88bd200e14f")
# Top folder inside the archive.
set(BULLET_UPSTREAM_TOPDIR "pybullet-3.2.7")

# What is unpacked (paths relative to the top folder). The libraries upstream
# installs need the first group (with upstream's .bullet file loader and world
# importer, which patch 0017 teaches the plastic constraints and which only the
# tests build); the demo app (OpenGL / OSMesa) needs the second (three headers that
# OpenGLExampleBrowser.cpp includes). Both are always unpacked, since patches
# 0008-0011 change files of the second group; only what a target needs is built.
set(BULLET_UPSTREAM_LIBRARY_PATHS
	LICENSE.txt
	src/LinearMath
	src/Bullet3Common
	src/BulletCollision
	src/BulletDynamics
	src/BulletInverseDynamics
	src/BulletSoftBody
	src/btBulletCollisionCommon.h
	src/btBulletDynamicsCommon.h
	src/btBulletCollisionAll.cpp
	src/btBulletDynamicsAll.cpp
	src/btLinearMathAll.cpp
	Extras/Serialize/BulletFileLoader
	Extras/Serialize/BulletWorldImporter)
set(BULLET_UPSTREAM_DEMO_PATHS
	examples/OpenGLWindow
	examples/CommonInterfaces
	examples/ExampleBrowser
	examples/Utils
	examples/ThirdPartyLibs/glad
	examples/ThirdPartyLibs/stb_image
	examples/ThirdPartyLibs/Gwen
	examples/ThirdPartyLibs/optionalX11
	examples/Importers/ImportURDFDemo/ImportURDFSetup.h
	examples/Importers/ImportBullet/SerializeSetup.h
	examples/SharedMemory/SharedMemoryPublic.h)

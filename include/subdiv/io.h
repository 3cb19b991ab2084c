#pragma once
/// \file
/// subdiv's io module: reading and writing OBJ, PLY, OFF, glTF and STL files.

#include "subdiv/io/file_io.h"
#include "subdiv/io/gltf.h"
#include "subdiv/io/mesh_io.h"
#include "subdiv/io/obj.h"
#include "subdiv/io/off.h"
#include "subdiv/io/ply.h"
#include "subdiv/io/stl.h"

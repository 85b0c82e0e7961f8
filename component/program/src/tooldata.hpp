// libtooldata (LinuxCNC 2.9, linked by librs274) installs no header: the functions the reader
// uses, declared as LinuxCNC's src/emc/tooldata/tooldata.hh of 2.9 declares them. Internal.
#pragma once

#include <emctool.h>

class EMC_TOOL_STAT;

enum toolidx_t { IDX_OK = 0, IDX_NEW, IDX_FAIL };
CANON_TOOL_TABLE tooldata_entry_init();
toolidx_t tooldata_put(CANON_TOOL_TABLE tdata, int idx);
toolidx_t tooldata_get(CANON_TOOL_TABLE* pdata, int idx);
int tooldata_load(const char* filename, char* ttcomments[]);
int tool_mmap_creator(EMC_TOOL_STAT const* ptr, int random_toolchanger);

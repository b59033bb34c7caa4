/* fgr kernel library: materials and their BSDFs (being written, issue 13). */

/* fgr kernel library: signed distance functions (being written). */

/* fgr kernel library: the path tracer's sample generator (being written, issue 13). */

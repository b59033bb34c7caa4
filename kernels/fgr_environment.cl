/* fgr kernel library: environment lighting, lookup and importance sampling (being written, issue 13). */

// SPDX-License-Identifier: Apache-2.0
// The source of the libraries that only build the host's shared precompiled headers
// (FgrHostLibrary.cmake): nothing of its own.

// SPDX-License-Identifier: Apache-2.0
#include "cli.hpp"
#include "distributed/cluster.hpp"

int main(int argc, char** argv) {
    // Joins the MPI job when mpirun started fgr on several ranks (distributed/cluster.hpp).
    fgr::ClusterSession session(&argc, &argv);
    return fgr::run_cli(argc, argv);
}

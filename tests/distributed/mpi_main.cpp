// SPDX-License-Identifier: MIT
// The main of the tests that run under mpiexec: MPI with one thread calling
// it, one worker per rank (the ranks already share the cores), the result
// printed by rank 0 only, and the same exit status on every rank. With the
// DMPlex bridge, PETSc is initialised on top of MPI.
#include <cgogn/core/parallel/thread_pool.h>

#ifdef CGOGN_TEST_DMPLEX
#include <petscsys.h>
#endif

#include <gtest/gtest.h>

#include <mpi.h>

int main(int argc, char** argv)
{
	int provided = 0;
	MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);
	::testing::InitGoogleTest(&argc, argv);
#ifdef CGOGN_TEST_DMPLEX
	// no options from the command line or a file: gtest's are not PETSc's
	PetscInitializeNoArguments();
#endif
	cgogn::set_nb_workers(1);
	int rank = 0;
	MPI_Comm_rank(MPI_COMM_WORLD, &rank);
	if (rank != 0)
	{
		auto& listeners = ::testing::UnitTest::GetInstance()->listeners();
		delete listeners.Release(listeners.default_result_printer());
	}
	const int failed = RUN_ALL_TESTS();
	int any_failed = 0;
	MPI_Allreduce(&failed, &any_failed, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
#ifdef CGOGN_TEST_DMPLEX
	PetscFinalize();
#endif
	MPI_Finalize();
	return any_failed;
}

// with_file_limit BYTES PROGRAM [ARGUMENTS...]: runs PROGRAM with no file allowed to grow past BYTES
// and SIGXFSZ ignored, so a write past the limit fails with EFBIG as a write onto a full disk fails
// with ENOSPC. The end-to-end tests use it to fill the disk without root and without a real disk.
#include <sys/resource.h>
#include <unistd.h>

#include <csignal>
#include <cstdio>
#include <cstdlib>

int main(int argc, char *argv[])
{
    if (argc < 3) {
        std::fprintf(stderr, "usage: with_file_limit BYTES PROGRAM [ARGUMENTS...]\n");
        return 125;
    }

    // the limit and the ignored signal both survive exec
    char *end = nullptr;
    const unsigned long long bytes = std::strtoull(argv[1], &end, 10);
    rlimit limit{};
    if (*end != '\0' || getrlimit(RLIMIT_FSIZE, &limit) != 0) {
        std::fprintf(stderr, "with_file_limit: bad limit %s\n", argv[1]);
        return 125;
    }
    limit.rlim_cur = static_cast<rlim_t>(bytes);
    if (setrlimit(RLIMIT_FSIZE, &limit) != 0 || std::signal(SIGXFSZ, SIG_IGN) == SIG_ERR) {
        std::perror("with_file_limit");
        return 125;
    }
    execv(argv[2], argv + 2);
    std::perror("with_file_limit: exec");
    return 127;
}

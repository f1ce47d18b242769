#include "subprocess.h"

#include "meshdiff/error.h"

#include <fcntl.h>
#include <fmt/format.h>
#include <poll.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <filesystem>

extern char** environ;

namespace meshdiff::cli {

std::string self_executable()
{
    std::error_code ec;
    const auto p = std::filesystem::read_symlink("/proc/self/exe", ec);
    if (ec) throw IoError(fmt::format("cannot find meshdiff's own executable: {}", ec.message()));
    return p.string();
}

ChildResult run_child(const std::string& program, const std::vector<std::string>& args, double timeout_seconds,
                      bool (*stop)())
{
    int out_pipe[2], err_pipe[2];
    if (pipe2(out_pipe, O_CLOEXEC) != 0) throw IoError(fmt::format("pipe: {}", std::strerror(errno)));
    if (pipe2(err_pipe, O_CLOEXEC) != 0) {
        close(out_pipe[0]);
        close(out_pipe[1]);
        throw IoError(fmt::format("pipe: {}", std::strerror(errno)));
    }
    std::vector<char*> argv;
    for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    const pid_t parent = getpid();
    const pid_t pid = fork();
    if (pid == 0) {
        // The child: it dies with this process (kill -9 of batch included), and
        // if this process is already gone it does not start.
        prctl(PR_SET_PDEATHSIG, SIGKILL);
        if (getppid() != parent) _exit(127);
        const int devnull = open("/dev/null", O_RDONLY);
        if (devnull < 0 || dup2(devnull, 0) < 0 || dup2(out_pipe[1], 1) < 0 || dup2(err_pipe[1], 2) < 0) _exit(127);
        execv(program.c_str(), argv.data());
        _exit(127);
    }
    const int rc = pid < 0 ? errno : 0;
    close(out_pipe[1]);
    close(err_pipe[1]);
    if (rc != 0) {
        close(out_pipe[0]);
        close(err_pipe[0]);
        throw IoError(fmt::format("{}: cannot start: {}", program, std::strerror(rc)));
    }

    ChildResult r;
    using clock = std::chrono::steady_clock;
    const auto deadline = clock::now() + std::chrono::duration<double>(timeout_seconds);
    auto kill_at = clock::time_point::max();  // SIGKILL after a SIGTERM that was not obeyed
    pollfd fds[2] = {{out_pipe[0], POLLIN, 0}, {err_pipe[0], POLLIN, 0}};
    std::string* sink[2] = {&r.out, &r.err};
    int open_fds = 2;
    char buf[1 << 16];
    while (open_fds > 0) {
        int wait_ms = -1;
        if (timeout_seconds > 0 && !r.timed_out) {
            const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - clock::now()).count();
            if (left <= 0) {
                kill(pid, SIGKILL);
                r.timed_out = true;
            } else {
                wait_ms = int(std::min<long long>(left, 1000));
            }
        }
        if (stop) {
            if (!r.stopped && stop()) {
                kill(pid, SIGTERM);
                r.stopped = true;
                kill_at = clock::now() + std::chrono::seconds(5);
            } else if (r.stopped && clock::now() >= kill_at) {
                kill(pid, SIGKILL);
                kill_at = clock::time_point::max();
            }
            wait_ms = wait_ms < 0 ? 100 : std::min(wait_ms, 100);
        }
        const int n = poll(fds, 2, wait_ms);
        if (n < 0 && errno != EINTR) break;
        for (int k = 0; k < 2; ++k) {
            if (fds[k].fd < 0 || !(fds[k].revents & (POLLIN | POLLHUP | POLLERR))) continue;
            const ssize_t got = read(fds[k].fd, buf, sizeof buf);
            if (got > 0) {
                sink[k]->append(buf, std::size_t(got));
            } else if (got == 0 || errno != EINTR) {
                close(fds[k].fd);
                fds[k].fd = -1;
                --open_fds;
            }
        }
    }
    int status = 0;
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {}
    if (WIFEXITED(status)) r.exit_code = WEXITSTATUS(status);
    if (WIFSIGNALED(status)) r.signal = WTERMSIG(status);
    return r;
}

}  // namespace meshdiff::cli

#include "subcommands.hpp"

#ifdef PEDNAV_HAVE_INSPECT
#include "cmd_inspect.hpp"
#endif
#ifdef PEDNAV_HAVE_SIM
#include "cmd_sim.hpp"
#endif
#ifdef PEDNAV_HAVE_EVAL
#include "cmd_eval.hpp"
#endif
#ifdef PEDNAV_HAVE_REPORT
#include "cmd_report.hpp"
#endif
#ifdef PEDNAV_HAVE_DEMO
#include "cmd_demo.hpp"
#endif

const std::vector<PednavSubcommand>& pednav_subcommands() {
    static const std::vector<PednavSubcommand> table = {
#ifdef PEDNAV_HAVE_INSPECT
        {"inspect", &pednav_cmd_inspect},
#endif
#ifdef PEDNAV_HAVE_SIM
        {"sim", &pednav_cmd_sim},
#endif
#ifdef PEDNAV_HAVE_EVAL
        {"eval", &pednav_cmd_eval},
#endif
#ifdef PEDNAV_HAVE_REPORT
        {"report", &pednav_cmd_report},
#endif
#ifdef PEDNAV_HAVE_DEMO
        {"demo", &pednav_cmd_demo},
#endif
    };
    return table;
}

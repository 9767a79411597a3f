#include "subcommands.hpp"

#include "cmd_inspect.hpp"
#include "cmd_sim.hpp"
#include "cmd_eval.hpp"
#include "cmd_report.hpp"
#include "cmd_demo.hpp"

const std::vector<PednavSubcommand>& pednav_subcommands() {
    static const std::vector<PednavSubcommand> table = {
        {"inspect", &pednav_cmd_inspect},
        {"sim", &pednav_cmd_sim},
        {"eval", &pednav_cmd_eval},
        {"report", &pednav_cmd_report},
        {"demo", &pednav_cmd_demo},
    };
    return table;
}

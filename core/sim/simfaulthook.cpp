#include "sim/simfaulthook.h"

#include "sim/faultinjector.h"

namespace mbscope {

Simulator::FaultHook faultHookFor(FaultInjector *injector)
{
    return [injector](const SimExchange &exchange) {
        return injector->plan(exchange);
    };
}

} // namespace mbscope

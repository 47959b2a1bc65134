// scripted-meter.js: the script of the scripted-meter profile (docs/profiles.md, "Scripts").
// A pulse meter whose answers are computed:
//   holding 0  counts up by one on every tick (the profile's tickMs: every 500 ms)
//   holding 1  counts the requests the meter has served
//   holding 2  read alone: the seconds since the script was loaded
//   holding 100-103, the meter's unfinished calibration block: any read there answers an
//   exception computed from the request: 03 (illegal data value) when more than 4 registers are
//   asked for, 02 (illegal data address) otherwise.
// Everything else is the profile's answer (onRequest returns undefined).

var served = 0;

function onTick(time) {
    unit.write("holding", 0, (unit.read("holding", 0) + 1) % 65536);
}

function onRequest(request) {
    served++;
    unit.write("holding", 1, served % 65536);
    if (request.function === 3 && request.address >= 100 && request.address <= 103) {
        var code = request.quantity > 4 ? 3 : 2;
        log("calibration block read at", request.address, "x" + request.quantity, "by", request.peer,
            "-> exception", code);
        return { exception: code };
    }
    if (request.function === 3 && request.address === 2 && request.quantity === 1)
        return [Math.floor(request.time / 1000) % 65536];
    return undefined;
}

// em340-meter.js: the script of the em340-meter profile (docs/profiles.md, "Devices for inference").
// A real meter measures voltages, currents and power factors and computes the rest from them; so
// does this one. The profile's generators move the phase voltages (0-5), currents (12-17), power
// factors (46-48) and the frequency; before every answer (onRequest) and every tick this script
// computes from them, as the meter does, so that no read sees new voltages beside old powers:
//   VA Ln  = V Ln-N x A Ln                  (24-29)
//   W Ln   = VA Ln x PF Ln                  (18-23)
//   var Ln = sqrt(VA^2 - W^2), + inductive on L1 and L2, - capacitive on L3   (30-35)
//   V L-L  = the line-to-line voltage of two phases 120 degrees apart (6-11)
//   sys    = the mean of the phase voltages, the sums of the powers, PF sys = W sys / VA sys (36-45, 49)
//   kWh, kvarh = W sys and |var sys| integrated over time (52-55)
// 32-bit values are signed, low word first (CDAB), at the profile's scales.

var kwh = 45678.9;
var kvarh = 8123.4;
var last = -1;

function read32(address, scale) {
    var lo = unit.read("holding", address);
    var hi = unit.read("holding", address + 1);
    var raw = hi * 65536 + lo;
    if (raw >= 2147483648)
        raw -= 4294967296;
    return raw * scale;
}

function write32(address, value, scale) {
    var raw = Math.round(value / scale);
    if (raw < 0)
        raw += 4294967296;
    unit.write("holding", address, [raw % 65536, Math.floor(raw / 65536)]);
}

function read16(address, scale) {
    var raw = unit.read("holding", address);
    return (raw >= 32768 ? raw - 65536 : raw) * scale;
}

// The values computed from the measured ones; returns W sys and var sys.
function compute() {
    var sign = [1, 1, -1];
    var w = 0, va = 0, vars = 0, vln = 0;
    var v = [];
    for (var p = 0; p < 3; ++p) {
        v.push(read32(2 * p, 0.1));
        var a = read32(12 + 2 * p, 0.001);
        var pf = read16(46 + p, 0.001);
        var s = v[p] * a;
        var pw = s * pf;
        var q = sign[p] * Math.sqrt(Math.max(0, s * s - pw * pw));
        write32(24 + 2 * p, s, 0.1);
        write32(18 + 2 * p, pw, 0.1);
        write32(30 + 2 * p, q, 0.1);
        w += pw;
        va += s;
        vars += q;
        vln += v[p];
    }
    var vll = 0;
    for (var k = 0; k < 3; ++k) {
        var x = v[k], y = v[(k + 1) % 3];
        var ll = Math.sqrt(x * x + y * y + x * y);
        write32(6 + 2 * k, ll, 0.1);
        vll += ll;
    }
    write32(36, vln / 3, 0.1);
    write32(38, vll / 3, 0.1);
    write32(40, w, 0.1);
    write32(42, va, 0.1);
    write32(44, vars, 0.1);
    unit.write("holding", 49, Math.round(1000 * w / va));
    return {w: w, vars: vars};
}

function onRequest(request) {
    compute();
    return undefined; // the tables answer
}

function onTick(time) {
    var sys = compute();
    var w = sys.w, vars = sys.vars;
    if (last >= 0) {
        var hours = (time - last) / 3600000;
        kwh += w * hours / 1000;
        kvarh += Math.abs(vars) * hours / 1000;
    }
    last = time;
    write32(52, kwh, 0.1);
    write32(54, kvarh, 0.1);
}

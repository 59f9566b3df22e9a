using OperatorPanel.Core.Protocol;

namespace OperatorPanel.Simulator.Reference;

/// <summary>
/// A small bottling line run on a <see cref="ReferencePlc"/> by simulated time only (no clocks), one scan every
/// 10 ms. Uses what samples/bottling-line.opproj shows: inputs I0.0-I1.5, outputs Q0.0-Q1.1, bottle counter VD100
/// (unsigned, big-endian), bottles per minute VW104, machine state VB110, running seconds MW10, litres filled
/// VD120 (REAL, 0.5 l per bottle) and alarms M2.0-M2.7. Every value follows from the elapsed time alone.
/// </summary>
public sealed class DemoProcess
{
    public static readonly TimeSpan ScanPeriod = TimeSpan.FromMilliseconds(10);

    private readonly ReferencePlc _plc;
    private TimeSpan _pending;
    private long _scans;
    private bool _lastBottleSensor;

    public DemoProcess(ReferencePlc plc)
    {
        ArgumentNullException.ThrowIfNull(plc);
        _plc = plc;
    }

    /// <summary>Simulated time run so far, in whole scans.</summary>
    public TimeSpan Elapsed => ScanPeriod * _scans;

    public void Advance(TimeSpan elapsed)
    {
        ArgumentOutOfRangeException.ThrowIfLessThan(elapsed, TimeSpan.Zero);
        _pending += elapsed;
        while (_pending >= ScanPeriod)
        {
            _pending -= ScanPeriod;
            _scans++;
            Scan((long)Elapsed.TotalMilliseconds);
        }
    }

    private void Scan(long ms)
    {
        var m = _plc.Memory;
        var second = ms / 1000;
        var inCycle = ms % 60_000;

        // Field inputs: switch on, paused 40-45 s of every minute, guard door open 20-23 s, a bottle every second.
        var conveyorWasOn = m.GetBit(ProtocolArea.Q, 0, 0);
        m.SetBit(ProtocolArea.I, 0, 0, inCycle is < 40_000 or >= 45_000);
        m.SetBit(ProtocolArea.I, 0, 1, inCycle is >= 40_000 and < 40_200);
        m.SetBit(ProtocolArea.I, 0, 2, conveyorWasOn && ms % 1000 < 300);
        m.SetBit(ProtocolArea.I, 0, 3, second / 5 % 2 == 0);
        m.SetBit(ProtocolArea.I, 0, 4, true);
        m.SetBit(ProtocolArea.I, 0, 5, inCycle is < 20_000 or >= 23_000);
        m.SetBit(ProtocolArea.I, 0, 6, true);
        m.SetBit(ProtocolArea.I, 0, 7, second / 7 % 2 == 0);
        m.SetBit(ProtocolArea.I, 1, 0, m.GetBit(ProtocolArea.Q, 0, 1));
        m.SetBit(ProtocolArea.I, 1, 1, true);
        for (var bit = 2; bit <= 5; bit++)
        {
            m.SetBit(ProtocolArea.I, 1, bit, ((second % 16) & (1 << (bit - 2))) != 0);
        }

        if (_plc.Mode == OperatingMode.Run)
        {
            RunProgram(m, ms, second);
        }

        // Scan times 3-6 ms in a fixed pattern, so SMW22/24/26 show something plausible and repeatable.
        _plc.CompleteScan((ushort)(3 + (_scans % 4)));
    }

    private void RunProgram(PlcMemory m, long ms, long second)
    {
        var running = m.GetBit(ProtocolArea.I, 0, 0) && m.GetBit(ProtocolArea.I, 0, 4) && m.GetBit(ProtocolArea.I, 0, 5);
        var bottle = m.GetBit(ProtocolArea.I, 0, 2);
        if (running && bottle && !_lastBottleSensor)
        {
            var count = m.ReadDoubleWord(ProtocolArea.V, 100) + 1;
            m.WriteDoubleWord(ProtocolArea.V, 100, count);
            m.WriteDoubleWord(ProtocolArea.V, 120, BitConverter.SingleToUInt32Bits(count * 0.5f));
        }

        _lastBottleSensor = bottle;
        if (running && ms % 1000 == 0)
        {
            m.WriteWord(ProtocolArea.M, 10, (ushort)(m.ReadWord(ProtocolArea.M, 10) + 1));
        }

        // M2.0 guard door open, M2.1 line paused, M2.2-M2.7 come and go: bit k on for (k + 1) s every 30 s.
        byte alarms = 0;
        alarms |= (byte)(m.GetBit(ProtocolArea.I, 0, 5) ? 0 : 0x01);
        alarms |= (byte)(m.GetBit(ProtocolArea.I, 0, 0) ? 0 : 0x02);
        for (var k = 2; k < 8; k++)
        {
            alarms |= (byte)((second + (5 * k)) % 30 <= k ? 1 << k : 0);
        }

        m.M[2] = alarms;
        m.WriteWord(ProtocolArea.V, 104, (ushort)(running ? 60 : 0));
        m.V[110] = (byte)(alarms != 0 ? 2 : running ? 1 : 0);

        Drive(0, 0, running);
        Drive(0, 1, running && bottle);
        Drive(0, 2, running);
        Drive(0, 3, alarms != 0);
        Drive(0, 4, (alarms & 0x01) != 0);
        Drive(0, 5, running && m.GetBit(ProtocolArea.I, 0, 6));
        Drive(0, 6, running && m.GetBit(ProtocolArea.I, 0, 7));
        Drive(0, 7, false);
        Drive(1, 0, running && ms / 500 % 2 == 0);
        Drive(1, 1, false);
    }

    /// <summary>An output the panel has written keeps the panel's value.</summary>
    private void Drive(int offset, int bit, bool value)
    {
        if (!_plc.IsOwnedByPanel(offset, bit))
        {
            _plc.Memory.SetBit(ProtocolArea.Q, offset, bit, value);
        }
    }
}

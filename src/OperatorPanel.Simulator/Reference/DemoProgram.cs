using System.Text;
using OperatorPanel.Core.Protocol;
using static OperatorPanel.Simulator.Reference.DemoSymbols;

namespace OperatorPanel.Simulator.Reference;

/// <summary>
/// The PLC program of the demo filler, as a technician would expect it from samples/bottling-line.opproj: run/stop,
/// the fill sequence (<see cref="DemoFillStep"/>), counting at the outfeed, tank refill and the outputs. Alarms are
/// in DemoProgram.Alarms.cs. Outputs the panel has written keep the panel's value (<see cref="IDemoPlc.IsOwnedByPanel"/>).
/// </summary>
internal sealed partial class DemoProgram(IDemoPlc plc)
{
    private const int HeadTravelMs = 200;
    private const int ReleaseMs = 200;

    /// <summary>The fill-position eye sees a bottle 70 ms before it stands at the stop; wait for it to settle.</summary>
    private const int SettleMs = 100;
    private const int RejectPushMs = 300;
    private const int BatchSize = 50;

    // The bottle already on its way out at the start is a good one.
    private readonly Queue<bool> _underfilledOnTheWay = new([false]);
    private readonly DemoLineSpeed _speed = new();
    private bool _recipeLoaded;
    private DemoFillStep _step;
    private int _stepMs;
    private bool _underfilled;
    private bool _lastStart;
    private bool _lastOutfeed;
    private bool _pumpOn;
    private int _rejectMs;

    /// <summary>The line was already running when the demo starts.</summary>
    public bool Running { get; private set; } = true;

    public void Scan(PlcMemory m, long ms, double tankLevel)
    {
        if (!_recipeLoaded)
        {
            LoadRecipe(m);
        }

        var alarms = LatchAlarms(m, tankLevel);
        var start = StartButton.Get(m);
        if ((alarms & DemoAlarms.Faults) != 0 || !StopButton.Get(m) || !AutoMode.Get(m))
        {
            Running = false;
        }
        else if (start && !_lastStart && GuardDoorClosed.Get(m))
        {
            Running = true;
        }

        _lastStart = start;
        if (Running && RunSequence(m))
        {
            alarms |= DemoAlarms.FillTime;
        }

        Outfeed(m, ms);
        _pumpOn = EStopHealthy.Get(m) && (TankLevelLow.Get(m) || (_pumpOn && !TankLevelHigh.Get(m)));
        m.WriteWord(ProtocolArea.V, TankLevel, (ushort)Math.Round(tankLevel));
        m.WriteWord(ProtocolArea.V, LineSpeed, _speed.BottlesPerMinute(ms));
        WriteAlarms(m, alarms);
        WriteStatus(m);
        Drive(ConveyorRun, Running);
        Drive(FillValve, Running && _step == DemoFillStep.Filling);
        Drive(BottleStop, _step != DemoFillStep.Release);
        Drive(FillHeadDown, Running && _step is DemoFillStep.HeadDown or DemoFillStep.Filling);
        Drive(TankPump, _pumpOn);
        Drive(LampRunning, Running);
        Drive(RejectPusher, _rejectMs > 0);
    }

    /// <summary>Recipe 3 (first scan, as SM0.1 would): 500 ml in at most 0.8 s, batch B042.</summary>
    private void LoadRecipe(PlcMemory m)
    {
        m.WriteWord(ProtocolArea.V, FillTimeMs, 800);
        m.V[RecipeNumber] = 3;
        m.WriteDoubleWord(ProtocolArea.V, FillSetpoint, BitConverter.SingleToUInt32Bits(500f));
        Encoding.ASCII.GetBytes("B042").CopyTo(m.V, BatchCode);
        _recipeLoaded = true;
    }

    /// <summary>Advances the fill sequence one scan; true when the fill time ran out on this scan.</summary>
    private bool RunSequence(PlcMemory m)
    {
        _stepMs += DemoProcess.ScanMs;
        // FillTimeMs VW104 is signed; a value the panel wrote outside 0.1-10 s is kept within it.
        var fillLimitMs = Math.Clamp((int)(short)m.ReadWord(ProtocolArea.V, FillTimeMs), 100, 10_000);
        var full = BottleFull.Get(m);
        var atHead = FillPosition.Get(m);
        _stepMs = _step == DemoFillStep.WaitBottle && !atHead ? 0 : _stepMs;
        var timedOut = _step == DemoFillStep.Filling && !full && _stepMs >= fillLimitMs;
        var next = _step switch
        {
            DemoFillStep.WaitBottle when atHead && _stepMs >= SettleMs => DemoFillStep.HeadDown,
            DemoFillStep.HeadDown when _stepMs >= HeadTravelMs => DemoFillStep.Filling,
            DemoFillStep.Filling when full || timedOut => DemoFillStep.HeadUp,
            DemoFillStep.HeadUp when _stepMs >= HeadTravelMs => DemoFillStep.Release,
            DemoFillStep.Release when _stepMs >= ReleaseMs && !atHead => DemoFillStep.WaitBottle,
            DemoFillStep.WaitBottle or DemoFillStep.HeadDown or DemoFillStep.Filling or DemoFillStep.HeadUp or DemoFillStep.Release => _step,
        };
        if (next == _step)
        {
            return false;
        }

        _underfilled = next == DemoFillStep.HeadUp ? timedOut : _underfilled;
        if (next == DemoFillStep.Release)
        {
            _underfilledOnTheWay.Enqueue(_underfilled);
        }

        _step = next;
        _stepMs = 0;
        return timedOut;
    }

    /// <summary>Counts each bottle reaching the outfeed eye; an underfilled one is pushed off and counted as a reject.</summary>
    private void Outfeed(PlcMemory m, long ms)
    {
        _rejectMs = Math.Max(0, _rejectMs - DemoProcess.ScanMs);
        var outfeed = OutfeedBottle.Get(m);
        if (outfeed && !_lastOutfeed)
        {
            if (_underfilledOnTheWay.TryDequeue(out var underfilled) && underfilled)
            {
                _rejectMs = RejectPushMs;
                m.WriteDoubleWord(ProtocolArea.V, RejectCount, m.ReadDoubleWord(ProtocolArea.V, RejectCount) + 1);
            }
            else
            {
                var count = m.ReadDoubleWord(ProtocolArea.V, BottleCount) + 1;
                m.WriteDoubleWord(ProtocolArea.V, BottleCount, count);
                _speed.Count(ms);
                _batchMs = count % BatchSize == 0 ? BatchMessageMs : _batchMs;
            }
        }

        _lastOutfeed = outfeed;
    }

    /// <summary>StatusWord MW10: bit n = step n, bit 8 running, bit 9 a fault, bit 10 pump, bit 11 a reject on its way.</summary>
    private void WriteStatus(PlcMemory m)
    {
        var status = (1 << (int)_step)
            | (Running ? 1 << 8 : 0)
            | ((m.M[AlarmByte] & (byte)DemoAlarms.Faults) != 0 ? 1 << 9 : 0)
            | (_pumpOn ? 1 << 10 : 0)
            | (_underfilledOnTheWay.Contains(true) ? 1 << 11 : 0);
        m.WriteWord(ProtocolArea.M, StatusWord, (ushort)status);
        SequenceRunning.Set(m, Running && _step is DemoFillStep.HeadDown or DemoFillStep.Filling or DemoFillStep.HeadUp);
    }

    private void Drive(DemoBit output, bool value)
    {
        if (!plc.IsOwnedByPanel(output.Offset, output.Bit))
        {
            output.Set(plc.Memory, value);
        }
    }
}

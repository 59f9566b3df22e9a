using OperatorPanel.Core.Protocol;
using static OperatorPanel.Simulator.Reference.DemoSymbols;

namespace OperatorPanel.Simulator.Reference;

/// <summary>
/// The machine side of the demo line: bottles carried by the conveyor past three photo eyes, the fill head with its
/// level probe, the product tank with its pump and level switches, and the scripted disturbances (<see cref="DemoScript"/>).
/// It obeys the outputs as they stand in Q memory, whether the program or the panel set them, and writes the inputs.
/// </summary>
internal sealed class DemoField
{
    // Conveyor positions in mm from the infeed eye (I0.5). A bottle is 70 mm wide: an eye sees it within 35 mm.
    private const int ComesOnAt = -60;
    private const int FillPlace = 150; //          I0.6, where the bottle stop Q0.2 holds a bottle under the head
    private const int OutfeedEye = 450; //         I0.7 and the reject pusher Q1.1
    private const int LeavesAt = 600;
    private const int HalfWidth = 35;
    private const int MmPerScan = 5; //            0.5 m/s
    private const int HeadTravelMs = 150;
    private const double FlowMlPerMs = 0.8; //     500 ml in 0.63 s
    private const double SlowFlowMlPerMs = 0.45;
    private const double MlPerLevelUnit = 100; //  a 100 l tank, level in 0.1 %
    private const double PumpUnitsPerScan = 0.1; // 1 % per second
    private const int HighSwitch = 850;
    private const int LowSwitch = 200;
    private const int FallenBottleLiftedAfterMs = 8_000;

    // At the start the line is already at work: a full bottle on its way out, an empty one under the head.
    private readonly List<DemoBottle> _bottles = [new(0, FillPlace + 150) { Volume = 500 }, new(1, FillPlace)];
    private int _nextSerial = 2;
    private int _headMs;
    private bool _jamArmed;

    /// <summary>Product tank level in 0.1 % (0-1000); a shift starts with the tank low and the pump refilling it.</summary>
    public double TankLevel { get; private set; } = 150;

    /// <summary>True when nothing stops the line: e-stop released, door shut, motor and air fine, no fallen bottle.</summary>
    public bool IsHealthy(long ms) =>
        !DemoScript.EStopPressed(ms) && !DemoScript.GuardDoorOpen(ms) && !DemoScript.MotorTripped(ms)
        && !DemoScript.AirPressureLow(ms) && !_bottles.Exists(b => b.Fallen);

    /// <summary>One scan of physics, driven by the outputs in <paramref name="m"/>.</summary>
    public void Step(PlcMemory m, long ms)
    {
        var conveyor = ConveyorRun.Get(m);
        _jamArmed |= DemoScript.JamStarts(ms);
        Move(conveyor, BottleStop.Get(m));
        _headMs = Math.Clamp(_headMs + (FillHeadDown.Get(m) ? DemoProcess.ScanMs : -DemoProcess.ScanMs), 0, HeadTravelMs);
        if (FillValve.Get(m) && _headMs == HeadTravelMs && UnderHead() is { } bottle && TankLevel > 0)
        {
            var ml = (DemoScript.FillsSlowly(bottle.Serial) ? SlowFlowMlPerMs : FlowMlPerMs) * DemoProcess.ScanMs;
            bottle.Volume += ml;
            TankLevel = Math.Max(0, TankLevel - (ml / MlPerLevelUnit));
        }

        if (TankPump.Get(m))
        {
            TankLevel = Math.Min(1000, TankLevel + PumpUnitsPerScan);
        }

        if (RejectPusher.Get(m))
        {
            _bottles.RemoveAll(b => Sees(OutfeedEye, b));
        }

        if (conveyor && !_bottles.Exists(b => b.Position <= FillPlace))
        {
            _bottles.Add(new DemoBottle(_nextSerial++, ComesOnAt) { Fallen = _jamArmed });
            _jamArmed = false;
        }

        foreach (var fallen in _bottles.Where(b => b.Fallen && b.Position == 0))
        {
            fallen.LyingMs += DemoProcess.ScanMs;
        }

        _bottles.RemoveAll(b => b.LyingMs >= FallenBottleLiftedAfterMs || b.Position >= LeavesAt);
    }

    public void WriteInputs(PlcMemory m, long ms, DemoOperator person)
    {
        EStopHealthy.Set(m, !DemoScript.EStopPressed(ms));
        StartButton.Set(m, person.StartPressed);
        StopButton.Set(m, !DemoScript.StopPressed(ms));
        ResetButton.Set(m, person.ResetPressed);
        AutoMode.Set(m, true);
        InfeedBottle.Set(m, _bottles.Exists(b => Sees(0, b)));
        FillPosition.Set(m, _bottles.Exists(b => Sees(FillPlace, b)));
        OutfeedBottle.Set(m, _bottles.Exists(b => Sees(OutfeedEye, b)));
        TankLevelHigh.Set(m, TankLevel >= HighSwitch);
        TankLevelLow.Set(m, TankLevel < LowSwitch);
        BottleFull.Set(m, _headMs == HeadTravelMs && UnderHead() is { } bottle && bottle.Volume >= ProbeMl(m));
        GuardDoorClosed.Set(m, !DemoScript.GuardDoorOpen(ms));
        ConveyorMotorOk.Set(m, !DemoScript.MotorTripped(ms));
        AirPressureOk.Set(m, !DemoScript.AirPressureLow(ms));
    }

    private static bool Sees(int eye, DemoBottle bottle) => Math.Abs(bottle.Position - eye) <= HalfWidth;

    /// <summary>The level probe is set to the recipe's volume, FillSetpoint VD120 (kept to a bottle's 50-2000 ml).</summary>
    private static double ProbeMl(PlcMemory m)
    {
        var setpoint = BitConverter.UInt32BitsToSingle(m.ReadDoubleWord(ProtocolArea.V, FillSetpoint));
        return float.IsFinite(setpoint) ? Math.Clamp(setpoint, 50, 2000) : 500;
    }

    private DemoBottle? UnderHead() => _bottles.Find(b => b.Position == FillPlace);

    /// <summary>Bottles are kept front first; each moves unless the stop, the bottle ahead or its fall holds it.</summary>
    private void Move(bool conveyor, bool stopOut)
    {
        if (!conveyor)
        {
            return;
        }

        var ahead = int.MaxValue;
        foreach (var bottle in _bottles)
        {
            var next = Math.Min(bottle.Position + MmPerScan, ahead - (2 * HalfWidth));
            if (stopOut && bottle.Position <= FillPlace)
            {
                next = Math.Min(next, FillPlace);
            }

            if (bottle.Fallen)
            {
                next = Math.Min(next, 0);
            }

            bottle.Position = Math.Max(bottle.Position, next);
            ahead = bottle.Position;
        }
    }
}

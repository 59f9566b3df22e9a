using OperatorPanel.Core.Protocol;

namespace OperatorPanel.Simulator.Reference;

/// <summary>The addresses of samples/bottling-line.opproj, by symbol, as the demo line uses them.</summary>
internal static class DemoSymbols
{
    public static readonly DemoBit EStopHealthy = new(ProtocolArea.I, 0, 0); //    NC chain: 0 = pressed
    public static readonly DemoBit StartButton = new(ProtocolArea.I, 0, 1); //     NO
    public static readonly DemoBit StopButton = new(ProtocolArea.I, 0, 2); //      NC: 0 = pressed
    public static readonly DemoBit ResetButton = new(ProtocolArea.I, 0, 3);
    public static readonly DemoBit AutoMode = new(ProtocolArea.I, 0, 4);
    public static readonly DemoBit InfeedBottle = new(ProtocolArea.I, 0, 5);
    public static readonly DemoBit FillPosition = new(ProtocolArea.I, 0, 6);
    public static readonly DemoBit OutfeedBottle = new(ProtocolArea.I, 0, 7);
    public static readonly DemoBit TankLevelHigh = new(ProtocolArea.I, 1, 0);
    public static readonly DemoBit TankLevelLow = new(ProtocolArea.I, 1, 1); //    1 = level below the low switch
    public static readonly DemoBit BottleFull = new(ProtocolArea.I, 1, 2);
    public static readonly DemoBit GuardDoorClosed = new(ProtocolArea.I, 1, 3);
    public static readonly DemoBit ConveyorMotorOk = new(ProtocolArea.I, 1, 4);
    public static readonly DemoBit AirPressureOk = new(ProtocolArea.I, 1, 5);

    public static readonly DemoBit ConveyorRun = new(ProtocolArea.Q, 0, 0);
    public static readonly DemoBit FillValve = new(ProtocolArea.Q, 0, 1);
    public static readonly DemoBit BottleStop = new(ProtocolArea.Q, 0, 2); //      1 = cylinder out, holding the bottle
    public static readonly DemoBit FillHeadDown = new(ProtocolArea.Q, 0, 3);
    public static readonly DemoBit TankPump = new(ProtocolArea.Q, 0, 4);
    public static readonly DemoBit LampRunning = new(ProtocolArea.Q, 0, 5);
    public static readonly DemoBit LampFault = new(ProtocolArea.Q, 0, 6);
    public static readonly DemoBit LampLowProduct = new(ProtocolArea.Q, 0, 7);
    public static readonly DemoBit Horn = new(ProtocolArea.Q, 1, 0);
    public static readonly DemoBit RejectPusher = new(ProtocolArea.Q, 1, 1);

    public static readonly DemoBit SequenceRunning = new(ProtocolArea.M, 0, 0);

    /// <summary>MB2: the alarm flags M2.0-M2.7 (<see cref="DemoAlarms"/>).</summary>
    public const int AlarmByte = 2;

    /// <summary>MW10: sequence status bits (<see cref="DemoFillStep"/> one-hot in bits 0-4, see DemoProgram).</summary>
    public const int StatusWord = 10;

    // Byte offsets in V memory; words and double words are big-endian (PlcMemory).
    public const int BottleCount = 100; //  VD100 unsigned
    public const int FillTimeMs = 104; //   VW104 signed, longest valve open time per bottle
    public const int RecipeNumber = 110; // VB110
    public const int FillSetpoint = 120; // VD120 REAL, ml
    public const int BatchCode = 130; //    VD130 four ASCII characters
    public const int LineSpeed = 140; //    VW140 bottles per minute
    public const int RejectCount = 144; //  VD144 unsigned
    public const int TankLevel = 150; //    VW150 signed, 0.1 %
    public const int FaultCode = 160; //    VB160
}

namespace OperatorPanel.Simulator.Reference;

/// <summary>The alarm flags M2.0-M2.7 of samples/bottling-line.opproj, as the bits of MB2.</summary>
[Flags]
internal enum DemoAlarms : byte
{
    None = 0,

    /// <summary>M2.0 "Emergency stop pressed" (fault, acknowledge).</summary>
    EmergencyStop = 1 << 0,

    /// <summary>M2.1 "Bottle jam at infeed" (fault, acknowledge).</summary>
    Jam = 1 << 1,

    /// <summary>M2.2 "Low product level in tank" (warning).</summary>
    LowProduct = 1 << 2,

    /// <summary>M2.3 "Guard door opened during operation" (fault, acknowledge).</summary>
    GuardDoor = 1 << 3,

    /// <summary>M2.4 "Conveyor motor overload" (fault, acknowledge).</summary>
    MotorOverload = 1 << 4,

    /// <summary>M2.5 "Compressed air pressure low" (fault, acknowledge).</summary>
    AirPressure = 1 << 5,

    /// <summary>M2.6 "Fill time exceeded: check the fill valve" (warning, acknowledge).</summary>
    FillTime = 1 << 6,

    /// <summary>M2.7 "Batch complete" (information).</summary>
    BatchComplete = 1 << 7,

    /// <summary>The fault class: any of these stops the line.</summary>
    Faults = EmergencyStop | Jam | GuardDoor | MotorOverload | AirPressure,

    /// <summary>Latched until the Reset button (I0.3) is pressed with the cause gone.</summary>
    NeedAcknowledgement = Faults | FillTime,
}

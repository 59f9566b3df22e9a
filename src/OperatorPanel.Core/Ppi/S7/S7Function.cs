namespace OperatorPanel.Core.Ppi.S7;

/// <summary>The first parameter byte of a job or its answer (libnodave nodave.h "daveFunc..."; docs/ppi.md section 5).</summary>
public enum S7Function : byte
{
    ReadVariable = 0x04,
    WriteVariable = 0x05,

    /// <summary>PI service "P_PROGRAM" with 16#28 = RUN (libnodave paMakeRun, HslCommunication SiemensPPI.Start).</summary>
    PlcControl = 0x28,

    /// <summary>16#29 "P_PROGRAM" = STOP (libnodave paMakeStop, HslCommunication SiemensPPI.Stop).</summary>
    PlcStop = 0x29,

    /// <summary>Setup communication: the PDU size offered and agreed (libnodave _daveNegPDUlengthRequest).</summary>
    SetupCommunication = 0xF0,
}

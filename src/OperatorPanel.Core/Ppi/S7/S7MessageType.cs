namespace OperatorPanel.Core.Ppi.S7;

/// <summary>The S7 PDU's message type, header byte 1 ("ROSCTR"; libnodave doc/pdu.html "type 1,2,3 or 7").</summary>
public enum S7MessageType : byte
{
    /// <summary>A request from the master: 10-byte header.</summary>
    Job = 0x01,

    /// <summary>An acknowledgement without data, e.g. a refused job: 12-byte header with error class and code.</summary>
    Ack = 0x02,

    /// <summary>The answer to a job: 12-byte header with error class and code.</summary>
    AckData = 0x03,

    /// <summary>User data (diagnostics, programming): not spoken here.</summary>
    UserData = 0x07,
}

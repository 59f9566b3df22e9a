namespace OperatorPanel.Core.Ppi.S7;

/// <summary>
/// The per-item answer of a read or write (libnodave nodave.h and daveExecWriteRequest; HslCommunication
/// SiemensPPI.GetMsgFromStatus; docs/ppi.md section 7).
/// </summary>
public enum S7ReturnCode : byte
{
    /// <summary>Not an answer: the code byte of a write item in a request.</summary>
    Reserved = 0x00,

    /// <summary>"No data from I/O module" / "hardware fault".</summary>
    HardwareFault = 0x01,

    /// <summary>"Illegal object access": on the S7-200 also a data block other than 1 or a bit item of count other than 1.</summary>
    AccessDenied = 0x03,

    /// <summary>"The data address is beyond the CPU's address range".</summary>
    AddressOutOfRange = 0x05,

    DataTypeNotSupported = 0x06,

    /// <summary>"Write data size mismatch".</summary>
    DataTypeInconsistent = 0x07,

    /// <summary>"Object does not exist" (S7-300/400 family).</summary>
    ObjectDoesNotExist = 0x0A,

    Success = 0xFF,
}

namespace OperatorPanel.Core.Ppi.S7;

/// <summary>
/// The header's error class and code in our words (libnodave daveStrerror and doc/PDUerrorcodes.html; HslCommunication
/// SiemensPPI.GetMsgFromStatus for the S7-200's own wording; docs/ppi.md section 7).
/// </summary>
public static class S7ErrorText
{
    public static string Describe(int error) => error switch
    {
        0x8000 => "function already occupied",
        0x8001 => "not allowed in the CPU's current mode",
        0x8101 => "hardware fault",
        0x8103 => "object access not allowed",
        0x8104 => "the CPU does not support this job, or the job is malformed",
        0x8105 => "invalid address",
        0x8106 => "data type not supported",
        0x8107 => "data type not consistent",
        0x810A => "object does not exist",
        0x8404 => "the CPU is busy (upload or download) or in a system fault",
        0x8500 => "incorrect PDU size: the length fields do not agree with the data",
        0xD241 => "not allowed at the CPU's protection level (password)",
        _ when error >> 8 == 0xD6 => "protection error (password)",
        _ when error >> 8 == 0x80 => "the mode switch is in the wrong position for this job",
        _ => "error not known to the panel",
    };
}
